/** Derivation steps: a list of formulas (KaTeX), each with the reason the step is allowed. */
import { useRef, type ReactNode } from 'react';
import { MathTex } from '../../../ui';
import { useScrollBoxFocus } from './scrollFocus';

export interface StepLine {
  tex: string;
  /** Why this line follows (shown beside it), e.g. "identity sin θ cos θ = ½ sin 2θ". */
  why?: ReactNode;
}

export function Steps({ lines, label, testId }: { lines: StepLine[]; label: string; testId?: string }) {
  const list = useRef<HTMLOListElement>(null);
  // measured again when a formula changes (its live numbers), not on every render
  useScrollBoxFocus(list, lines.map((l) => l.tex).join('\n'));
  return (
    <ol className="hemi-steps" data-testid={testId} aria-label={label} ref={list}>
      {lines.map((l, i) => (
        <li key={i} className="hemi-step">
          {/* a scroll box: a wide formula scrolls sideways on a phone, then also from the keyboard */}
          <div className="deriv-formula" role="group" aria-label={`${label}, step ${i + 1}`}>
            <MathTex tex={l.tex} display />
          </div>
          {l.why ? <span className="hemi-why">{l.why}</span> : null}
        </li>
      ))}
    </ol>
  );
}
