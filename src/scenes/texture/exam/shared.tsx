/**
 * What the exam parts of Q3 share: the position a part shows (the moving query, its steps and its
 * answer always at one position), the "these are not the exam's numbers" line, the key-note
 * wording, and the frame of a part about the query (a) and (b): the steps, the live answer and the
 * key's note.
 */
import { useEffect, useMemo, useRef, useState, type ReactNode } from 'react';
import {
  Derivation,
  ExamPart,
  KeyNote,
  LiveAnswer,
  Readout,
  Revealed,
  TEXT_HZ,
  preloadMath,
  useAnimFrame,
  usePlaying,
  useStillT,
} from '../../../ui';
import { agreesWithKey, isExamQuery } from '../readouts';
import type { Frame } from '../path';
import type { Lookup } from '../model';
import type { AnimContext } from '../view/anim';
import { formatRounded } from '../../../core/format';
import './shared.css';

/** What a part about the query shows: the position, and the context it was computed in. */
export interface Shown {
  ctx: AnimContext;
  frame: Frame;
}

/**
 * The position a part shows: its worked steps, its answer and its notes all render at this one
 * frame, so the derivation and the answer under it never disagree. Paused (stepped, scrubbed,
 * edited) it is the exact position, at once (the steps' formula shows as plain text until it is
 * typeset: ./view/WorkedSteps' `exact` math). While it plays or a handle is dragged it follows the
 * moving query at most TEXT_HZ times a second, and a new position is shown only once its formulas
 * (`texOf`, the steps' blocks) are typeset, so the formulas and the numbers beside them change in
 * one render; one typeset is in flight at a time, and the latest position waits for it.
 */
export function useShownFrame(ctx: AnimContext, texOf: (s: Shown) => readonly string[]): Shown {
  const tStill = useStillT(ctx.store);
  const playing = usePlaying(ctx.store);
  const moves = playing || ctx.dragging;
  const exact = useMemo<Shown>(() => ({ ctx, frame: ctx.frame(tStill).frame }), [ctx, tStill]);
  const [moving, setMoving] = useState<Shown | null>(null);
  useEffect(() => {
    if (!moves) setMoving(null);
  }, [moves]);
  const alive = useRef(true);
  useEffect(() => {
    alive.current = true;
    return () => {
      alive.current = false;
    };
  }, []);
  const req = useRef({
    ctx: null as AnimContext | null,
    t: NaN,
    at: -Infinity,
    busy: false,
    next: null as Shown | null,
  });
  const latest = useRef(ctx);
  latest.current = ctx;
  const movingNow = () => latest.current.dragging || latest.current.store.livePlaying();
  useAnimFrame(ctx.store, (t, text) => {
    const r = req.current;
    const now = performance.now();
    if (!text || !movingNow()) return;
    if ((r.ctx === ctx && r.t === t) || now - r.at < 1000 / TEXT_HZ - 1) return;
    r.ctx = ctx;
    r.t = t;
    r.at = now;
    const run = (w: Shown) => {
      r.busy = true;
      void Promise.all(texOf(w).map((tex) => preloadMath(tex, true))).then(() => {
        // a typeset that ends after the pause (or the drop) is not shown: the exact position is
        if (alive.current && movingNow()) setMoving(w);
        r.busy = false;
        const n = r.next;
        r.next = null;
        if (n) run(n);
      });
    };
    const want = { ctx, frame: ctx.frame(t).frame };
    if (r.busy) r.next = want;
    else run(want);
  });
  return moves && moving ? moving : exact;
}

/** Whether the shown position is the exam's own query (grid, conventions and point). */
export const isExamShown = ({ ctx, frame }: Shown) => isExamQuery(ctx.src, ctx.opts, frame.u, frame.v);

/** "(u, v) = (0.52, 0.39) at t = 0.3": the shown point, named so it is not taken for the exam's. */
export function shownPoint({ frame }: Shown): string {
  return `(u, v) = (${formatRounded(frame.u)}, ${formatRounded(frame.v)})${frame.t !== 0 ? ` at t = ${formatRounded(frame.t)}` : ''}`;
}

/** A number shown plainly: six significant digits, or a dash when it is not finite. */
export function texPlain(x: number): string {
  return formatRounded(x, 6);
}

/** Whether a computed value agrees with the key's printed one, in words. */
export function keyNote(computed: number, printed: { value: number; decimals: number }): string {
  return agreesWithKey(computed, printed)
    ? `agrees with the key’s printed ${printed.value}`
    : `the key prints ${printed.value}; the computed value rounds to ${computed.toFixed(printed.decimals)}`;
}

function NotExam({ shown, toExam }: { shown: Shown; toExam: () => void }) {
  if (isExamShown(shown)) return null;
  const { src, opts } = shown.ctx;
  return (
    <p className="tx-small tx-not-exam" data-testid="not-exam-query">
      The steps and the answer use the point shown, {shownPoint(shown)}
      {shown.frame.t !== 0 ? ' on its path' : ''}
      {src.isExam ? '' : ', on a grid that is not the exam’s'}
      {opts.align !== 'corner' ? ', with texel centres' : ''}
      {opts.vflip ? ', with v flipped' : ''}; the exam asks at (0.4, 0.24).{' '}
      <button type="button" onClick={toExam} data-testid="to-exam">
        Back to the exam’s question
      </button>
    </p>
  );
}

/**
 * A part's answer block: its readout at the shown position (`pick` from the lookup) and, while
 * paused at the exam's own query, how it compares with the key's printed figure; `more` adds
 * readouts after it.
 */
export function answerOf(
  id: string,
  label: string,
  pick: (q: Lookup) => number,
  printed: { value: number; decimals: number },
  more?: (q: Lookup) => ReactNode,
): PartBody {
  return function Answer({ shown, playing }) {
    const q = shown.frame.lookup;
    const value = pick(q);
    const exam = !playing && isExamShown(shown);
    return (
      <div className="readouts">
        <Readout id={id} label={label} value={value} note={exam ? keyNote(value, printed) : undefined} />
        {more?.(q)}
      </div>
    );
  };
}

/** Props of an exam part about the query: (a) and (b). */
export interface QueryPartProps {
  ctx: AnimContext;
  /** Puts the exam's grid, query and conventions back. */
  toExam: () => void;
  /** Ask first: the steps, the answer and the key's note are hidden until revealed. */
  ask: boolean;
}

/** What each block of a part gets: the shown position, and whether the animation plays. */
export type PartBody = (props: { shown: Shown; playing: boolean }) => ReactNode;

/**
 * An exam part about the query, (a) or (b): the not-the-exam line, then its worked steps (whose
 * formulas are `texOf`), its live answer and the key's note, all at one shown position.
 */
export function queryPart(
  id: string,
  title: string,
  asks: string,
  texOf: (s: Shown) => readonly string[],
  [Worked, Answer, Note]: readonly [PartBody, PartBody, PartBody],
) {
  return function QueryPart({ ctx, toExam, ask }: QueryPartProps) {
    const shown = useShownFrame(ctx, texOf);
    const playing = usePlaying(ctx.store);
    return (
      <ExamPart id={id} title={title} asks={asks}>
        <NotExam shown={shown} toExam={toExam} />
        <Revealed ask={ask} what="the steps and the answer" minHeight="6rem">
          <Derivation testId={`derivation-${id}`}>
            <Worked shown={shown} playing={playing} />
          </Derivation>
          <LiveAnswer testId={`answer-${id}`}>
            <Answer shown={shown} playing={playing} />
          </LiveAnswer>
          <KeyNote testId={`keynote-${id}`}>
            <Note shown={shown} playing={playing} />
          </KeyNote>
        </Revealed>
      </ExamPart>
    );
  };
}
