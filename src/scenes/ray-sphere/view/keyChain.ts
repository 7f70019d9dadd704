/**
 * Key presses on a cross-section handle that come faster than frames. The scene applies at most
 * one edit per frame and the figure draws after it, so a press must step on from where the
 * previous press sent the handle, not from where it is drawn, or every press of a frame but one
 * would be lost. A chain remembers, for one handle, where its presses sent it (`at`), the value
 * the last one sent, and every value the figure may still show on the way there (the one shown
 * before the first press, and each sent since). Pure: values are compared as texts.
 */
import type { Target } from './crossLayout';

export interface KeyChain {
  target: Target;
  /** Where the last press sent the handle in the figure (the radius for `r`). */
  at: readonly [number, number] | number;
  /** The value the last press sent. */
  sent: string;
  /** Every value a draw may show while the chain's presses are still being applied. */
  seen: ReadonlySet<string>;
}

/**
 * The chain after a draw that shows `shown` for the chain's handle: ended (null) when the draw
 * shows the value last sent (the presses have all landed) or a value no press of the chain sent
 * (a link, a drag, the timeline moved the handle); else still open.
 */
export function afterDraw(chain: KeyChain | null, shown: string): KeyChain | null {
  if (!chain) return null;
  return shown === chain.sent || !chain.seen.has(shown) ? null : chain;
}

/** Where a press on `target` steps from: the chain's `at` when the chain is this handle's, else null (what is drawn). */
export function stepFrom(chain: KeyChain | null, target: Target): KeyChain['at'] | null {
  return chain?.target === target ? chain.at : null;
}

/**
 * The chain after a press on `target` that sent `sent` (moving the handle to `at`); `shown` is the
 * value drawn now, the start of a new chain when the press begins one (another handle's chain is
 * dropped).
 */
export function afterPress(
  chain: KeyChain | null,
  target: Target,
  at: KeyChain['at'],
  sent: string,
  shown: string,
): KeyChain {
  const ahead = chain?.target === target ? chain : null;
  return { target, at, sent, seen: new Set([...(ahead?.seen ?? [shown]), sent]) };
}
