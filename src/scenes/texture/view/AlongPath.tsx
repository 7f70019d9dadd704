/**
 * The query's path beyond its start: the path's shape and its end (u₂, v₂), and the value looked up
 * along it (nearest as steps, bilinear as a curve, the marker at the paused t), with its data as a
 * table and as two audio traces. This module is the content of the scene's "path" fold (./PathFold):
 * it is loaded, and the profile computed, only when the fold is opened.
 */
import { startTransition, useEffect, useMemo, useRef, useState } from 'react';
import type { SceneProps } from '../../../kit/scene';
import {
  AudioTrace,
  Revealed,
  ShowAsTable,
  nextTask,
  summarizeSeries,
  useAnimFrame,
  useStillT,
} from '../../../ui';
import { pathProfile } from '../pathProfile';
import type { TextureSchema } from '../params';
import type { AnimContext } from './anim';
import {
  describePathNow,
  describePathStructure,
  nearestEvents,
  pathEvents,
  pathSamples,
  pathTableRows,
  short,
} from './describe';
import { PathEnd, PathKindSelect } from './FigureParts';
import { PathPlot } from './PathPlot';
import './AlongPath.css';

/** The fold's content: the path's shape and end, then the value along it (held back when asking). */
export function AlongPath({
  ctx,
  params,
  setParams,
  present,
  ask,
}: Pick<SceneProps<TextureSchema>, 'params' | 'setParams'> & {
  ctx: AnimContext;
  present: boolean;
  ask: boolean;
}) {
  return (
    <>
      <div className="tx-path-shape">
        <PathKindSelect params={params} setParams={setParams} />
        <PathEnd params={params} setParams={setParams} />
      </div>
      <Revealed ask={ask} what="the value along the path">
        <AnimPathPlot ctx={ctx} present={present} />
      </Revealed>
    </>
  );
}

/**
 * True from one task after the component mounted: work that can wait for it (a figure below the
 * first screen of a phone) stays out of the page's first render, so loading has no long task.
 */
function useAfterMount(): boolean {
  const [on, setOn] = useState(false);
  useEffect(() => {
    let live = true;
    nextTask(() => {
      if (live) startTransition(() => setOn(true));
    });
    return () => {
      live = false;
    };
  }, []);
  return on;
}

/**
 * The value along the path with the marker at t (its curves are memoized inside), described in
 * words, with its data as a table and as two audio traces (bilinear with a tick at each cell
 * border, nearest with a tick at each step).
 */
function AnimPathPlot({ ctx, present }: { ctx: AnimContext; present: boolean }) {
  const ready = useAfterMount();
  const { grid, opts, path } = ctx;
  const profile = useMemo(() => (ready ? pathProfile(grid, opts, path) : null), [ready, grid, opts, path]);
  const data = useMemo(() => {
    if (!profile) return null;
    const samples = pathSamples(grid, opts, path);
    const sum = (ys: number[], yLabel: string) =>
      summarizeSeries(samples.ts, ys, { xLabel: 't', yLabel, format: short });
    return {
      samples,
      summary: `${sum(samples.bil, 'Bilinear')} ${sum(samples.near, 'Nearest')} ${describePathStructure(profile)}`,
      // bilinear with a tick at each cell border, nearest at each of its steps
      traces: [
        { name: 'bilinear', ys: samples.bil, events: pathEvents(profile) },
        { name: 'nearest', ys: samples.near, events: nearestEvents(profile) },
      ],
      rows: pathTableRows(grid, opts, path, profile),
    };
  }, [profile, grid, opts, path]);
  const t = useStillT(ctx.store);
  const q = ctx.frame(t).frame.lookup;
  const draw = useRef<((t: number, near: number, bil: number) => void) | null>(null);
  useAnimFrame(ctx.store, (x) => {
    const l = ctx.frame(x).frame.lookup;
    draw.current?.(x, l.near.value, l.bil.value);
  });
  const description = data
    ? `${data.summary} ${describePathNow(t, q.near.value, q.bil.value)}`
    : 'The value along the path is being computed.';
  return (
    <PathPlot
      profile={profile}
      t={t}
      near={q.near.value}
      bil={q.bil.value}
      present={present}
      description={description}
      drawRef={draw}
    >
      {data ? (
        <div className="tx-plot-a11y">
          <ShowAsTable
            caption="The looked-up value along the path"
            columns={['t', 'nearest', 'bilinear', 'on the path']}
            rows={data.rows}
            testId="path-table"
          />
          <details className="tx-listen" data-testid="path-listen">
            <summary>Listen to the plot</summary>
            {data.traces.map((tr) => (
              <AudioTrace
                key={tr.name}
                label={`${tr.name} along the path`}
                xs={data.samples.ts}
                ys={tr.ys}
                xLabel="t"
                yLabel={tr.name}
                events={tr.events}
                format={short}
                testId={`path-audio-${tr.name}`}
              />
            ))}
          </details>
        </div>
      ) : null}
    </PathPlot>
  );
}
