/** Q3(b): bilinear interpolation at the query, in the key's form, and what dropping the cell size does. */
import { KEY_PRINTED, agreesWithKey } from '../readouts';
import { formatRounded } from '../../../core/format';
import { BilinearWorked, bilinearBlocks } from '../view/WorkedSteps';
import { answerOf, isExamShown, queryPart, shownPoint, type PartBody } from './shared';

const Worked: PartBody = ({ shown: { ctx, frame } }) => <BilinearWorked opts={ctx.opts} q={frame.lookup} />;

/** The answer at the shown position. */
const Answer = answerOf('bilinear', 'Bilinear (Q3b)', (q) => q.bil.value, KEY_PRINTED.bilinear);

const cu = (
  <>
    c<sub>u</sub>
  </>
);
const cl = (
  <>
    c<sub>l</sub>
  </>
);

/** What dropping the division does, at the point shown (named when it is not the exam's). */
const Note: PartBody = ({ shown }) => {
  const q = shown.frame.lookup;
  const exam = isExamShown(shown);
  const agrees =
    agreesWithKey(q.steps.cu, KEY_PRINTED.cu) &&
    agreesWithKey(q.steps.cl, KEY_PRINTED.cl) &&
    agreesWithKey(q.steps.c, KEY_PRINTED.bilinear);
  return (
    <>
      the key deducts 2.5 marks when the division by the cell size (0.25 on the exam’s grid) is missing.
      Without it each step is scaled by Δ{exam ? '' : ` (at the point shown, ${shownPoint(shown)})`}: {cu}{' '}
      would be {formatRounded(q.steps.cu * q.bil.du)}, {cl} {formatRounded(q.steps.cl * q.bil.du)} and c{' '}
      {formatRounded(q.steps.c * q.bil.du * q.bil.dv)}
      {exam ? (
        <>
          ; with the divisions the computed {cu}, {cl} and c ({formatRounded(q.steps.cu)},{' '}
          {formatRounded(q.steps.cl)}, {formatRounded(q.steps.c)}) {agrees ? 'agree with' : 'differ from'} the
          key’s printed {KEY_PRINTED.cu.value}, {KEY_PRINTED.cl.value} and {KEY_PRINTED.bilinear.value}
        </>
      ) : null}
      .
    </>
  );
};

export const Q3b = queryPart(
  '3b',
  'Bilinear',
  'What value does bilinear interpolation give at (u, v) = (0.4, 0.24)?',
  ({ ctx, frame }) => bilinearBlocks(frame.lookup, ctx.opts),
  [Worked, Answer, Note],
);
