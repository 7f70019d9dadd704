/** Q3(a): nearest-neighbour lookup at the query, with the key's steps and the flipped-v convention. */
import { useDeferredValue, useMemo, useRef } from 'react';
import { LiveReadout, useAnimFrame, writeReadout } from '../../../ui';
import { KEY_PRINTED, lookupAt, queryReadouts } from '../model';
import type { AnimContext } from '../view/anim';
import { fmtShort } from '../view/GridView';
import { NearestWorked } from '../view/WorkedSteps';
import { keyNote, queryPart, useStillQuery, useWorked } from './shared';

export const Q3a = queryPart(
  '3a',
  'Nearest neighbour',
  'What value does nearest-neighbour lookup return at (u, v) = (0.4, 0.24)?',
  [WorkedNearest, Readouts3a, KeyNote3a],
);

function WorkedNearest({ ctx }: { ctx: AnimContext }) {
  const q = useDeferredValue(useWorked(ctx).frame.lookup);
  return <NearestWorked grid={ctx.grid} opts={ctx.opts} q={q} />;
}

/** The live answer at position t (written per frame; the key note only while paused). */
function Readouts3a({ ctx }: { ctx: AnimContext }) {
  const { ro, examQ } = useStillQuery(ctx);
  const near = useRef<HTMLOutputElement>(null);
  const uv = useRef<HTMLOutputElement>(null);
  useAnimFrame(ctx.store, (x, text) => {
    if (!text) return;
    const q = ctx.frame(x).frame.lookup;
    writeReadout(near.current, queryReadouts(q).nearest);
    writeReadout(uv.current, `(${fmtShort(q.bil.u)}, ${fmtShort(q.bil.v)})`);
  });
  return (
    <div className="readouts">
      <LiveReadout
        id="nearest"
        label="Nearest (Q3a)"
        outRef={near}
        note={examQ ? keyNote(ro.nearest, KEY_PRINTED.nearest) : undefined}
      />
      <LiveReadout id="query-uv" label="(u, v) as used" outRef={uv} />
    </div>
  );
}

function KeyNote3a({ ctx }: { ctx: AnimContext }) {
  const { frame } = useWorked(ctx);
  const { grid, opts } = ctx;
  const flipped = useMemo(
    () => lookupAt(grid, frame.u, frame.v, { ...opts, vflip: !opts.vflip }),
    [grid, frame.u, frame.v, opts],
  );
  return (
    <>
      the key gives the node (0.5, 0.25) with the value 18 and also awards marks for a stated different
      convention, for example v′ = 1 − v (v measured downward). With the flip{' '}
      {opts.vflip ? 'undone' : 'applied'} here, nearest gives {fmtShort(flipped.near.value)} (the node at (
      {fmtShort(flipped.near.nodeU)}, {fmtShort(flipped.near.nodeV)}) of the flipped frame) and bilinear{' '}
      {fmtShort(flipped.bil.value)}.
    </>
  );
}
