/**
 * The animated figures beside and under the grid: each renders at the paused position (useStillT)
 * and writes its moving nodes per frame without React (useAnimFrame); see ./anim.
 */
import {
  startTransition,
  useEffect,
  useMemo,
  useRef,
  useState,
  type ComponentProps,
  type ReactNode,
} from 'react';
import { texel } from '../../../core/texture';
import {
  AudioTrace,
  DescribedFigure,
  Notice,
  ShowAsTable,
  nextTask,
  summarizeSeries,
  useAnimFrame,
  usePlaying,
  useStillT,
} from '../../../ui';
import { addressingNotes, type Lookup } from '../model';
import { pathProfile } from '../pathProfile';
import type { SphereModel } from '../sphere';
import type { Preset } from '../params';
import type { AnimContext } from './anim';
import { GridView } from './GridView';
import { StencilDetail } from './StencilDetail';
import { formatRounded } from '../../../core/format';
import {
  describePathNow,
  describePathStructure,
  describeSphere,
  describeTexture,
  nearestEvents,
  pathEvents,
  pathSamples,
  pathTableRows,
  short,
  textureName,
} from './describe';
import { PathPlot } from './PathPlot';
import './animated.css';

/** The grid figure with the query at position t (the grid's layers are memoized inside). */
export function AnimGrid({
  ctx,
  ...rest
}: { ctx: AnimContext } & Omit<ComponentProps<typeof GridView>, 'q' | 'path' | 'drawRef'>) {
  const t = useStillT(ctx.store);
  const draw = useRef<((q: Lookup) => void) | null>(null);
  useAnimFrame(ctx.store, (x) => draw.current?.(ctx.frame(x).dq));
  return <GridView {...rest} q={ctx.frame(t).dq} path={ctx.path} drawRef={draw} />;
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
export function AnimPathPlot({ ctx, present }: { ctx: AnimContext; present: boolean }) {
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

/**
 * The query now, its stencil and the addressing notes, beside the grid. The numbers are written per
 * frame without React (text at most TEXT_HZ times a second while playing); the addressing notes
 * render while paused only (exact at the paused position).
 */
export function AnimSide({ ctx }: { ctx: AnimContext }) {
  const t = useStillT(ctx.store);
  const playing = usePlaying(ctx.store);
  const { frame, dq } = ctx.frame(t);
  const q = frame.lookup;
  const notes = useMemo(
    () => (playing ? [] : addressingNotes(frame.u, frame.v, ctx.opts, q)),
    [playing, frame, ctx.opts, q],
  );
  const nowRef = useRef<HTMLParagraphElement>(null);
  const stencil = useRef<((q: Lookup, text: boolean) => void) | null>(null);
  useAnimFrame(ctx.store, (x, text) => {
    const f = ctx.frame(x);
    stencil.current?.(f.dq, text);
    const p = nowRef.current;
    if (!p || !text) return;
    const l = f.frame.lookup;
    const parts = [
      x === 0 ? '' : ` at t = ${formatRounded(x)} on its path`,
      formatRounded(f.frame.u),
      formatRounded(f.frame.v),
      formatRounded(l.near.value),
      formatRounded(l.bil.value),
    ];
    for (let k = 0; k < parts.length; k++) {
      const el = p.children[k];
      if (el && el.textContent !== parts[k]) el.textContent = parts[k];
    }
  });
  return (
    <>
      <p className="tx-now" data-testid="query-now" ref={nowRef}>
        Query
        <span />: (u, v) = (<span />, <span />) → nearest <strong />, bilinear <strong />
      </p>
      <StencilDetail q={dq} drawRef={stencil} />
      <p className="tx-small tx-stencil-key">
        <span className="tx-key nearest" /> nearest node · <span className="tx-key cell" /> the bilinear cell:
        each of its four nodes is weighted by the area of the sub-rectangle opposite to it (same colour).
      </p>
      {notes.length ? (
        <Notice kind="info" testId="addressing-note">
          {notes.map((n) => (
            <span key={n} className="tx-note-line">
              {n}
            </span>
          ))}
        </Notice>
      ) : null}
    </>
  );
}

/**
 * The main figure (the grid, the query on its path, the value along it and the stencil beside it),
 * named and described at the still position: the description follows every parameter and the
 * paused position (while playing it holds, and is announced again on pause).
 */
export function DescribedMain({
  ctx,
  preset,
  sphere,
  point,
  normalize,
  editing,
  ask,
  children,
}: {
  ctx: AnimContext;
  preset: Preset;
  sphere: SphereModel;
  point: { x: number; y: number; z: number };
  normalize: boolean;
  /** The node being edited (null when not editing or none chosen). */
  editing: { i: number; j: number } | null;
  /** Ask first: the setup only (see describeTexture). */
  ask: boolean;
  children: ReactNode;
}) {
  const t = useStillT(ctx.store);
  const playing = usePlaying(ctx.store);
  const { frame } = ctx.frame(t);
  const { grid, opts, src, path } = ctx;
  const description = useMemo(
    () =>
      describeTexture({
        name: textureName(grid, preset, src.isExam),
        opts,
        frame,
        path,
        notes: addressingNotes(frame.u, frame.v, opts, frame.lookup),
        editing:
          editing && editing.i < grid.width && editing.j < grid.height
            ? { ...editing, value: texel(grid, editing.i, editing.j) }
            : null,
        sphere: describeSphere(sphere, point, normalize, ask),
        ask,
      }),
    [grid, preset, src.isExam, opts, frame, path, editing, sphere, point, normalize, ask],
  );
  return (
    <DescribedFigure
      label="Texel grid with the query point, its path, and the value along the path"
      description={description}
      playing={playing}
      testId="texture-figure"
    >
      {children}
    </DescribedFigure>
  );
}
