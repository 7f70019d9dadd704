/**
 * Two "explore further" panels of #/area-light: the three strategies' convergence against N, and
 * their run time against error (both computed in the worker, started when the panel is seen).
 */
import { memo, useEffect, useMemo, useRef } from 'react';
import type { LightStrategy } from '../../../core/lights';
import type { Failure } from '../../../core/failure';
import {
  Notice,
  Panel,
  Plot,
  SERIES,
  ShowAsTable,
  summarizeSeries,
  useSeenOnce,
  type MarkerSymbol,
  type PlotLayout,
  type PlotTrace,
} from '../../../ui';
import type { TimingPoint, convergence } from '../model';
import { STRATEGIES, STRATEGY_LABEL, STRATEGY_SHORT } from '../strategies';
import { fmt } from './format';

/** The shared series colours (contrast and colour-vision checked in both themes). */
const COLORS: Record<LightStrategy, string> = {
  area: SERIES[1],
  'solid-angle': SERIES[0],
  cosine: SERIES[2],
};
/** A marker shape per strategy, so that colour is never the only cue. */
const SYMBOLS: Record<LightStrategy, MarkerSymbol> = {
  area: 'circle',
  'solid-angle': 'square',
  cosine: 'diamond',
};

/**
 * A box that calls `onSeen` once it has come near the screen. The panel owns it (not the scene):
 * the panel mounts after the scene, so only the panel's own effect finds the box in the page.
 */
function useSeenBox(onSeen: () => void) {
  const box = useRef<HTMLDivElement>(null);
  const seen = useSeenOnce(box);
  useEffect(() => {
    if (seen) onSeen();
  }, [seen, onSeen]);
  return box;
}

/** One sentence per strategy from summarizeSeries, on log–log axes. */
function perStrategy(
  series: readonly { strategy: LightStrategy; x: ArrayLike<number>; y: ArrayLike<number> }[],
  xLabel: string,
  yLabel: string,
): string {
  return series
    .map(
      (c) => `${STRATEGY_LABEL[c.strategy]}: ${summarizeSeries(c.x, c.y, { xLabel, yLabel, logLog: true })}`,
    )
    .join(' ');
}

/**
 * What a log–log plot shows: its name (for screen readers; "(log–log)" is added), its test id, its
 * axis titles and its height (normal, classroom).
 */
interface LogLogSpec {
  label: string;
  testId: string;
  axes: readonly [x: string, y: string];
  heights: readonly [normal: number, present: number];
}

const CONVERGENCE_PLOT: LogLogSpec = {
  label: 'Absolute error and standard error of the three estimators against the number of samples N',
  testId: 'al-convergence-plot',
  axes: ['N (samples)', 'error'],
  heights: [300, 380],
};

const TIMING_PLOT: LogLogSpec = {
  label: 'RMSE over independent runs against the run time of one estimate, for the three strategies',
  testId: 'al-timing-plot',
  axes: ['time per estimate (ms)', 'RMSE'],
  heights: [280, 360],
};

/** A log–log plot (its legend in a row above it, as every plot's). */
function LogLogPlot({
  spec: { label, axes, heights, testId },
  present,
  ...rest
}: {
  spec: LogLogSpec;
  present: boolean;
  description: string;
  data: PlotTrace[];
}) {
  const layout: PlotLayout = {
    xaxis: { type: 'log', title: { text: axes[0] } },
    yaxis: { type: 'log', title: { text: axes[1] } },
    margin: { l: 56, r: 16, t: 40, b: 44 },
  };
  const height = heights[present ? 1 : 0];
  return <Plot label={`${label} (log–log)`} testId={testId} {...rest} height={height} layout={layout} />;
}

/** Absolute and standard error of the three strategies against N (`onSeen`: the panel came near the screen, start its job). */
export const ConvergencePanel = memo(function ConvergencePanel({
  conv,
  onSeen,
  present,
}: {
  conv: ReturnType<typeof convergence> | undefined;
  onSeen: () => void;
  present: boolean;
}) {
  const seenRef = useSeenBox(onSeen);
  const traces: PlotTrace[] = useMemo(() => {
    const out: PlotTrace[] = [];
    for (const c of conv ?? []) {
      out.push({
        x: Array.from(c.n),
        y: Array.from(c.absError),
        type: 'scatter',
        mode: 'lines+markers',
        name: STRATEGY_SHORT[c.strategy],
        legendgroup: c.strategy,
        line: { color: COLORS[c.strategy], width: 2 },
        marker: { color: COLORS[c.strategy], symbol: SYMBOLS[c.strategy], size: 6 },
      });
      out.push({
        x: Array.from(c.n),
        y: Array.from(c.stderr),
        type: 'scatter',
        mode: 'lines',
        name: `std. error, ${STRATEGY_SHORT[c.strategy]}`,
        legendgroup: c.strategy,
        showlegend: false,
        line: { color: COLORS[c.strategy], dash: 'dot', width: 1.5 },
      });
    }
    return out;
  }, [conv]);
  const { description, rows, columns } = useMemo(() => {
    const cs = conv ?? [];
    if (!cs.length)
      return {
        description: 'No convergence data yet: it is computed when this panel comes into view.',
        rows: [],
        columns: ['N'],
      };
    const abs = perStrategy(
      cs.map((c) => ({ strategy: c.strategy, x: c.n, y: c.absError })),
      'N',
      '|estimate − reference|',
    );
    const se = perStrategy(
      cs.map((c) => ({ strategy: c.strategy, x: c.n, y: c.stderr })),
      'N',
      'the standard error',
    );
    return {
      description: `${abs} ${se}`,
      rows: Array.from(cs[0].n, (n, i) => [n, ...cs.flatMap((c) => [c.absError[i], c.stderr[i]])]),
      columns: [
        'N',
        ...cs.flatMap((c) => [`|error|, ${STRATEGY_SHORT[c.strategy]}`, `σ, ${STRATEGY_SHORT[c.strategy]}`]),
      ],
    };
  }, [conv]);
  return (
    <Panel title="Convergence">
      <div ref={seenRef} />
      <LogLogPlot spec={CONVERGENCE_PLOT} present={present} description={description} data={traces} />
      <p className="al-note">
        Solid: |estimate − reference|. Dotted: the standard error s/√N the estimator reports. Both fall like N
        <sup>−½</sup>; the strategies differ by a constant.
      </p>
      <ShowAsTable
        caption="Absolute error and standard error against N, per strategy"
        columns={columns}
        rows={rows}
        testId="al-convergence-table"
      />
    </Panel>
  );
});

/** RMSE against run time per estimate (`onSeen`: the panel came near the screen, start its job). */
export const TimingPanel = memo(function TimingPanel({
  result,
  running,
  progress,
  error,
  onSeen,
  present,
}: {
  result: TimingPoint[] | undefined;
  running: boolean;
  progress: number;
  error: Failure | null;
  onSeen: () => void;
  present: boolean;
}) {
  const seenRef = useSeenBox(onSeen);
  const traces: PlotTrace[] = useMemo(() => {
    const pts = result ?? [];
    return STRATEGIES.map((s) => {
      // Sorted by run time, so the path never doubles back in x (a busy machine can time a larger N faster).
      const rows = pts
        .filter((r) => r.strategy === s && r.rmse > 0 && r.seconds > 0)
        .sort((a, b) => a.seconds - b.seconds);
      return {
        x: rows.map((r) => r.seconds * 1e3),
        y: rows.map((r) => r.rmse),
        text: rows.map((r) => `N = ${r.n}`),
        type: 'scatter',
        mode: 'lines+markers',
        name: STRATEGY_SHORT[s],
        line: { color: COLORS[s] },
        marker: { color: COLORS[s], symbol: SYMBOLS[s], size: 7 },
      };
    });
  }, [result]);
  const { description, rows } = useMemo(() => {
    const pts = (result ?? []).filter((r) => r.rmse > 0 && r.seconds > 0);
    const series = STRATEGIES.map((s) => {
      const mine = pts.filter((r) => r.strategy === s).sort((a, b) => a.seconds - b.seconds);
      return { strategy: s, x: mine.map((r) => r.seconds * 1e3), y: mine.map((r) => r.rmse) };
    });
    return {
      description: pts.length
        ? perStrategy(series, 'time in ms', 'RMSE')
        : 'No timings yet: they are measured when this panel comes into view.',
      rows: pts.map((r) => [
        STRATEGY_SHORT[r.strategy],
        String(r.n),
        fmt(r.seconds * 1e3, 3),
        fmt(r.rmse, 3),
      ]),
    };
  }, [result]);
  return (
    <Panel title="Run time against error">
      <div ref={seenRef} className="al-progress-slot">
        {running ? <progress max={1} value={progress} aria-label="Timing progress" /> : null}
      </div>
      {error ? <Notice kind="warn">Timing failed: {error.message}</Notice> : null}
      <LogLogPlot spec={TIMING_PLOT} present={present} description={description} data={traces} />
      <p className="al-note">
        Each point: N = 16 … 4096 samples, RMSE over 24 independent runs, run time measured in a worker on
        this machine (best of three; noisy when the machine is busy). Points are joined in order of run time,
        so the line never doubles back. Lower-left wins.
      </p>
      <ShowAsTable
        caption="RMSE against the run time of one estimate"
        columns={['strategy', 'N', 'time (ms)', 'RMSE']}
        rows={rows}
        testId="al-timing-table"
      />
    </Panel>
  );
});
