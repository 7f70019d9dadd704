/**
 * Ask, then reveal (`ask=1`): a scene shows its setup and hides its results until the class has
 * made its prediction. `<Revealed>` wraps each result a scene hides; the shell shows the prompt
 * (`<AskPrompt>`) with the Reveal button above the scene.
 */
import type { CSSProperties, ReactNode } from 'react';
import { useKeyHelp, type KeyHelp } from './shortcuts';
import './ask.css';

export interface RevealedProps {
  /** `mode.ask`: true until revealed. */
  ask: boolean;
  /** What is hidden, completing "Hidden until you reveal: …" (e.g. "the estimates"). */
  what: string;
  children: ReactNode;
  /** The placeholder's height (CSS length or px), so the page does not jump on reveal. */
  minHeight?: number | string;
  testId?: string;
}

/**
 * The children once revealed; until then a placeholder box in their place (the children are not
 * rendered at all, so nothing of the result is on the page or computed for it).
 */
export function Revealed({ ask, what, children, minHeight, testId = 'ask-hidden' }: RevealedProps) {
  if (!ask) return <>{children}</>;
  const style: CSSProperties | undefined = minHeight !== undefined ? { minHeight } : undefined;
  return (
    <div className="ask-hidden" data-testid={testId} style={style}>
      Hidden until you reveal: {what}
    </div>
  );
}

/** The key of Reveal (the shell listens for it), for the `?` list. */
const REVEAL_KEY: readonly KeyHelp[] = [{ keys: 'v', label: 'reveal the hidden results' }];

/** The prediction prompt above an `ask=1` scene: the question and the Reveal button (key `v`). */
export function AskPrompt({ text, onReveal }: { text: string; onReveal: () => void }) {
  useKeyHelp(REVEAL_KEY);
  return (
    <section className="ask-prompt" aria-labelledby="ask-prompt-h" data-testid="ask-prompt">
      <h2 id="ask-prompt-h" className="ask-prompt-title">
        Predict first
      </h2>
      <p className="ask-prompt-text" data-testid="ask-prompt-text">
        {text}
      </p>
      <button
        type="button"
        className="ask-reveal"
        data-testid="reveal"
        aria-keyshortcuts="v"
        onClick={onReveal}
      >
        Reveal <kbd aria-hidden="true">v</kbd>
      </button>
    </section>
  );
}
