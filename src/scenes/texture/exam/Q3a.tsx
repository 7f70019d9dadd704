/** Q3(a): nearest-neighbour lookup at the query, with the key's steps and the flipped-v convention. */
import { useMemo } from 'react';
import { Readout } from '../../../ui';
import { KEY_PRINTED } from '../readouts';
import { lookupAt } from '../model';
import { formatRounded } from '../../../core/format';
import { NearestWorked, nearestBlocks } from '../view/WorkedSteps';
import { answerOf, isExamShown, queryPart, shownPoint, type PartBody } from './shared';

const Worked: PartBody = ({ shown: { ctx, frame } }) => (
  <NearestWorked grid={ctx.grid} opts={ctx.opts} q={frame.lookup} />
);

/** The answer at the shown position, and the (u, v) the lookup used. */
const Answer = answerOf(
  'nearest',
  'Nearest (Q3a)',
  (q) => q.near.value,
  KEY_PRINTED.nearest,
  (q) => (
    <Readout
      id="query-uv"
      label="(u, v) as used"
      value={`(${formatRounded(q.bil.u)}, ${formatRounded(q.bil.v)})`}
    />
  ),
);

/**
 * The key's figures are the exam point's; the flipped lookup is computed at the point shown and
 * says which point that is whenever it is not the exam's.
 */
const Note: PartBody = ({ shown }) => {
  const { ctx, frame } = shown;
  const { grid, opts } = ctx;
  const flipped = useMemo(
    () => lookupAt(grid, frame.u, frame.v, { ...opts, vflip: !opts.vflip }),
    [grid, frame.u, frame.v, opts],
  );
  const exam = isExamShown(shown);
  return (
    <>
      {exam ? 'the key' : 'at the exam’s point (0.4, 0.24) the key'} gives the node (0.5, 0.25) with the value{' '}
      {KEY_PRINTED.nearest.value} and also awards marks for a stated different convention, for example v′ = 1
      − v (v measured downward).{' '}
      {exam
        ? 'With the flip applied here'
        : `At the point shown, ${shownPoint(shown)}, with the flip ${opts.vflip ? 'undone' : 'applied'}`}
      , nearest gives {formatRounded(flipped.near.value)} (the node at ({formatRounded(flipped.near.nodeU)},{' '}
      {formatRounded(flipped.near.nodeV)}) of the flipped frame) and bilinear{' '}
      {formatRounded(flipped.bil.value)}.
    </>
  );
};

export const Q3a = queryPart(
  '3a',
  'Nearest neighbour',
  'What value does nearest-neighbour lookup return at (u, v) = (0.4, 0.24)?',
  ({ ctx, frame }) => nearestBlocks(ctx.grid, frame.lookup, ctx.opts),
  [Worked, Answer, Note],
);
