/**
 * What the exam parts of Q3 share: the worked position (the committed path, held while playing),
 * the "these are not the exam's numbers" line, the key-note wording, and the frame of a part about
 * the query (a) and (b): the steps, the live answer and the key's note.
 */
import type { ReactNode } from 'react';
import { Derivation, ExamPart, KeyNote, LiveAnswer, usePlaying, useStillT } from '../../../ui';
import { agreesWithKey, isExamQuery, queryReadouts } from '../model';
import type { AnimContext } from '../view/anim';
import { fmtShort } from '../view/GridView';

/**
 * The worked steps follow the committed path; while playing they hold the position where it
 * started (exact again as soon as it pauses, steps or seeks), so no frame carries a KaTeX typeset.
 */
export function useWorked(ctx: AnimContext) {
  const tWorked = useStillT(ctx.store);
  return { tWorked, frame: ctx.worked(tWorked) };
}

/**
 * The live answer's values at the still position, and whether the query there is the exam's (only
 * while paused: the key's note is not shown mid-play).
 */
export function useStillQuery(ctx: AnimContext) {
  const t = useStillT(ctx.store);
  const playing = usePlaying(ctx.store);
  const { frame } = ctx.frame(t);
  const ro = queryReadouts(frame.lookup);
  const examQ = !playing && isExamQuery(ctx.src, ctx.opts, frame.u, frame.v);
  return { ro, examQ };
}

/** A number shown plainly: six significant digits, or a dash when it is not finite. */
export function texPlain(x: number): string {
  return Number.isFinite(x) ? String(Number(x.toPrecision(6))) : '—';
}

/** Whether a computed value agrees with the key's printed one, in words. */
export function keyNote(computed: number, printed: { value: number; decimals: number }): string {
  return agreesWithKey(computed, printed)
    ? `agrees with the key’s printed ${printed.value}`
    : `the key prints ${printed.value}; the computed value rounds to ${computed.toFixed(printed.decimals)}`;
}

function NotExam({ ctx, toExam }: { ctx: AnimContext; toExam: () => void }) {
  const { tWorked, frame } = useWorked(ctx);
  const { src, opts } = ctx;
  if (isExamQuery(src, opts, frame.u, frame.v)) return null;
  return (
    <p className="tx-small tx-not-exam" data-testid="not-exam-query">
      The steps use the current query (u, v) = ({fmtShort(frame.u)}, {fmtShort(frame.v)})
      {tWorked !== 0 ? `, at t = ${fmtShort(tWorked)} on its path` : ''}
      {src.isExam ? '' : ', on a grid that is not the exam’s'}
      {opts.align !== 'corner' ? ', with texel centres' : ''}
      {opts.vflip ? ', with v flipped' : ''}.{' '}
      <button type="button" onClick={toExam} data-testid="to-exam">
        Back to the exam’s question
      </button>
    </p>
  );
}

/** Props of an exam part about the query: (a) and (b). */
export interface QueryPartProps {
  ctx: AnimContext;
  /** Puts the exam's grid, query and conventions back. */
  toExam: () => void;
}

type PartBody = (props: { ctx: AnimContext }) => ReactNode;

/**
 * An exam part about the query, (a) or (b): the not-the-exam line, then its worked steps, its live
 * answer and the key's note, each a component of the animation context.
 */
export function queryPart(
  id: string,
  title: string,
  asks: string,
  [Worked, Answer, Note]: readonly [PartBody, PartBody, PartBody],
) {
  return function QueryPart({ ctx, toExam }: QueryPartProps) {
    return (
      <ExamPart id={id} title={title} asks={asks}>
        <NotExam ctx={ctx} toExam={toExam} />
        <Derivation testId={`derivation-${id}`}>
          <Worked ctx={ctx} />
        </Derivation>
        <LiveAnswer testId={`answer-${id}`}>
          <Answer ctx={ctx} />
        </LiveAnswer>
        <KeyNote testId={`keynote-${id}`}>
          <Note ctx={ctx} />
        </KeyNote>
      </ExamPart>
    );
  };
}
