/** Q3(b): bilinear interpolation at the query, in the key's form, and what dropping the cell size does. */
import { useDeferredValue, useRef } from 'react';
import { LiveReadout, useAnimFrame, writeReadout } from '../../../ui';
import { KEY_PRINTED, agreesWithKey, isExamQuery, queryReadouts } from '../model';
import type { AnimContext } from '../view/anim';
import { fmtShort } from '../view/GridView';
import { BilinearWorked } from '../view/WorkedSteps';
import { keyNote, queryPart, useStillQuery, useWorked } from './shared';

export const Q3b = queryPart(
  '3b',
  'Bilinear',
  'What value does bilinear interpolation give at (u, v) = (0.4, 0.24)?',
  [WorkedBilinear, Readouts3b, KeyNote3b],
);

function WorkedBilinear({ ctx }: { ctx: AnimContext }) {
  const q = useDeferredValue(useWorked(ctx).frame.lookup);
  return <BilinearWorked opts={ctx.opts} q={q} />;
}

/** The live answer at position t (written per frame; the key note only while paused). */
function Readouts3b({ ctx }: { ctx: AnimContext }) {
  const { ro, examQ } = useStillQuery(ctx);
  const bil = useRef<HTMLOutputElement>(null);
  useAnimFrame(ctx.store, (x, text) => {
    if (text) writeReadout(bil.current, queryReadouts(ctx.frame(x).frame.lookup).bilinear);
  });
  return (
    <div className="readouts">
      <LiveReadout
        id="bilinear"
        label="Bilinear (Q3b)"
        outRef={bil}
        note={examQ ? keyNote(ro.bilinear, KEY_PRINTED.bilinear) : undefined}
      />
    </div>
  );
}

function KeyNote3b({ ctx }: { ctx: AnimContext }) {
  const { frame } = useWorked(ctx);
  const q = useDeferredValue(frame.lookup);
  const exam = isExamQuery(ctx.src, ctx.opts, frame.u, frame.v);
  const printed = `${KEY_PRINTED.cu.value}, ${KEY_PRINTED.cl.value} and ${KEY_PRINTED.bilinear.value}`;
  const agrees =
    agreesWithKey(q.steps.cu, KEY_PRINTED.cu) &&
    agreesWithKey(q.steps.cl, KEY_PRINTED.cl) &&
    agreesWithKey(q.steps.c, KEY_PRINTED.bilinear);
  const computed = `${fmtShort(q.steps.cu)}, ${fmtShort(q.steps.cl)}, ${fmtShort(q.steps.c)}`;
  return (
    <>
      the key deducts 2.5 marks when the division by the cell size 0.25 is missing. Without it each step is
      scaled by Δ: c_u would be {fmtShort(q.steps.cu * q.bil.du)}, c_l {fmtShort(q.steps.cl * q.bil.du)} and c{' '}
      {fmtShort(q.steps.c * q.bil.du * q.bil.dv)}
      {exam
        ? `; with the divisions the computed c_u, c_l and c (${computed}) ` +
          `${agrees ? 'agree with' : 'differ from'} the key’s printed ${printed}`
        : ''}
      .
    </>
  );
}
