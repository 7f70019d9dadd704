/**
 * The figures' accessible side at the sweep's coarse position: each figure's name and live
 * description (ui/describe), and for the two plots their data as a table and as an audio trace.
 * These parts re-render at most RENDER_HZ times a second while the sweep plays (the figures they
 * wrap are passed in as children and are not re-rendered with them).
 */
import { useMemo, useState, type ReactNode } from 'react';
import {
  AudioTrace,
  DescribedFigure,
  ShowAsTable,
  useTimelineFrame,
  type AudioTraceProps,
  type ShowAsTableProps,
} from '../../../ui';
import type { RaySphereHit } from '../../../core/geometry';
import type { RaySphereModel } from '../model';
import type { Sweep } from '../sweep';
import type { SweepSeries } from '../sweepSeries';
import { useCoarseModel, type LiveProps } from './Live';
import { deltaEvents, describeDeltaPlot, describeGPlot, gEvents, gSamples, num } from './describe';
import { sweepCoord } from './format';

/** Whether the timeline plays, as React state (changes on play and pause only). */
function usePlaying(tl: LiveProps['tl']): boolean {
  const [playing, setPlaying] = useState(tl.playing);
  useTimelineFrame(tl, (_t, p) => {
    if (p !== playing) setPlaying(p);
  });
  return playing;
}

/**
 * A figure named `label` whose description is `describe(model, τ)` at the coarse position: spoken
 * after input settles and on pause (not while playing), on `d`, and always its accessible
 * description. `after` renders under the figure from the same model (tables, audio traces).
 */
export function LiveDescribed({
  tl,
  modelAt,
  label,
  describe,
  quiet,
  testId,
  className,
  children,
  after,
}: LiveProps & {
  label: string;
  describe: (m: RaySphereModel, tau: number) => string;
  quiet?: boolean;
  testId: string;
  className?: string;
  children: ReactNode;
  after?: (m: RaySphereModel, tau: number) => ReactNode;
}) {
  const { t, model } = useCoarseModel({ tl, modelAt });
  const playing = usePlaying(tl);
  return (
    <>
      <DescribedFigure
        label={label}
        description={describe(model, t)}
        playing={playing}
        quiet={quiet}
        testId={testId}
        className={className}
      >
        {children}
      </DescribedFigure>
      {after ? after(model, t) : null}
    </>
  );
}

/** One axis of a plot's data: its name (spoken and in the table) and its values. */
interface Axis {
  label: string;
  values: ArrayLike<number>;
}

/**
 * A plot's data heard (an audio trace: y against x, with its events) and read (a table), under
 * the plot; their test ids are `<id>-trace` and `<id>-table`.
 */
function PlotData({
  id,
  label,
  x,
  y,
  events,
  table,
}: {
  id: string;
  /** What the audio trace follows. */
  label: string;
  x: Axis;
  y: Axis;
  events: AudioTraceProps['events'];
  table: Pick<ShowAsTableProps, 'caption' | 'columns' | 'rows'>;
}) {
  const trace = { label, events, xs: x.values, ys: y.values, xLabel: x.label, yLabel: y.label };
  return (
    <div className="rs-plot-data">
      <AudioTrace {...trace} format={(v) => num(v, 3)} testId={`${id}-trace`} />
      <ShowAsTable {...table} testId={`${id}-table`} />
    </div>
  );
}

/** g(t) at the current ray as a table and an audio trace (events at its roots). */
export function GPlotData({ res, window: w }: { res: RaySphereHit | null; window: SweepSeries['gWindow'] }) {
  const data = useMemo(() => (res ? gSamples(res, w) : { t: [], g: [] }), [res, w]);
  const events = useMemo(() => gEvents(res), [res]);
  return (
    <PlotData
      id="g"
      label="g(t) along the ray"
      x={{ label: 't', values: data.t }}
      y={{ label: 'g', values: data.g }}
      events={events}
      table={{
        caption: 'g(t) = a t² + b t + c along the ray at the current position',
        columns: ['t', 'g(t)'],
        rows: data.t.map((t, i) => [t, data.g[i]]),
      }}
    />
  );
}

export const gDescription = (w: SweepSeries['gWindow']) => (m: RaySphereModel) => describeGPlot(m.chosen, w);

/** Δ against the sweep as a table and an audio trace (events at the tangencies, Δ = 0). */
export function DeltaPlotData({
  series: s,
  tangentX,
  sweep,
}: {
  series: SweepSeries;
  tangentX: number[];
  sweep: Sweep;
}) {
  const coord = sweepCoord(sweep.mode);
  const events = useMemo(() => deltaEvents(tangentX, sweep.mode), [tangentX, sweep.mode]);
  const rows = useMemo(
    () => s.x.map((x, i) => [num(x, 4), num(s.discStable[i]), num(s.discNaive[i]), s.cases[i]]),
    [s],
  );
  return (
    <PlotData
      id="delta"
      label="robust Δ against the sweep"
      x={{ label: coord, values: s.x }}
      y={{ label: 'Δ', values: s.discStable }}
      events={events}
      table={{
        caption: `Δ against the sweep coordinate ${coord}: robust and textbook, and the case`,
        columns: [coord, 'robust Δ', 'textbook Δ', 'case'],
        rows,
      }}
    />
  );
}

/** The Δ plot's description at the coarse position (the robust Δ of the ray shown). */
export const deltaDescription =
  (s: SweepSeries, tangentX: number[], sweep: Sweep, xAt: (tau: number) => number) =>
  (m: RaySphereModel, tau: number) =>
    describeDeltaPlot(s, tangentX, sweep.mode, {
      x: xAt(tau),
      disc: m.rows.find((r) => r.method === 'stable')?.res.discriminant ?? null,
    });
