/** A race lane's readouts (newest sample, its term, the estimate, ± s/√N), written per frame. */
import { useRef } from 'react';
import { LiveReadout, writeReadout } from '../../../ui';
import type { LaneState } from '../race';

/** What a lane's ± s/√N reads when the terms' spread is zero to rounding (model.zeroToRounding). */
export const ZERO_TEXT = '0 (zero variance)';

/** The readouts of a lane: written directly (see drawLane), not rendered by React. */
export interface LaneRefs {
  x: React.RefObject<HTMLOutputElement | null>;
  term: React.RefObject<HTMLOutputElement | null>;
  estimate: React.RefObject<HTMLOutputElement | null>;
  stderr: React.RefObject<HTMLOutputElement | null>;
  /** The label's sample index (x<sub>n</sub>) and count (⟨I⟩ after n). */
  sub: React.RefObject<HTMLElement | null>;
  after: React.RefObject<HTMLSpanElement | null>;
}

export function useLaneRefs(): LaneRefs {
  return {
    x: useRef(null),
    term: useRef(null),
    estimate: useRef(null),
    stderr: useRef(null),
    sub: useRef(null),
    after: useRef(null),
  };
}

export function drawLane(r: LaneRefs, s: LaneState): void {
  writeReadout(r.x.current, s.n ? s.x : null, 6);
  writeReadout(r.term.current, s.n ? s.term : null, 6);
  writeReadout(r.estimate.current, s.n ? s.estimate : null, 7);
  writeReadout(r.stderr.current, s.n > 1 ? s.stderr : null, 3);
  // a spread that is rounding noise reads as what it is (the value itself stays in data-value)
  const el = r.stderr.current;
  if (el && s.zeroVariance && el.textContent !== ZERO_TEXT) el.textContent = ZERO_TEXT;
  const sub = String(s.n || 'i');
  if (r.sub.current && r.sub.current.textContent !== sub) r.sub.current.textContent = sub;
  const after = String(s.n);
  if (r.after.current && r.after.current.textContent !== after) r.after.current.textContent = after;
}

/** A lane's readouts: its newest sample and term, its estimate and ± s/√N (written per frame). */
export function LaneReadouts({ id, r }: { id: string; r: LaneRefs }) {
  return (
    <div className="readouts mc-lane-readouts mc-half">
      <LiveReadout
        id={`race-${id}-x`}
        label={
          <>
            x<sub ref={r.sub} />
          </>
        }
        outRef={r.x}
      />
      <LiveReadout id={`race-${id}-term`} label="its term f/p" outRef={r.term} />
      <LiveReadout
        id={`race-${id}-estimate`}
        label={
          <>
            ⟨I⟩ after <span ref={r.after} />
          </>
        }
        outRef={r.estimate}
      />
      <LiveReadout id={`race-${id}-stderr`} label="± s/√N" outRef={r.stderr} />
    </div>
  );
}
