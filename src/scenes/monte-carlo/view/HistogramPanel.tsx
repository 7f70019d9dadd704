/** Unbiasedness: the histogram of many independent estimates at fixed N, with their mean (core Welford). */
import { useMemo, useRef } from 'react';
import { formatNumber, Panel, Readout, useThrottled, type PlotTrace } from '../../../ui';
import { useAutoRun } from '../../../workers';
import { estimateFromTerms, histogram } from '../../../core/estimators';
import { REDRAW_MS, useLegendRoom } from './hooks';
import { arr, BAR_OPACITY, COLORS, CountField, REFERENCE, RunBar, type PanelRunProps } from './plotStyle';
import { DescribedPlot, type PlotWords } from './DescribedPlot';
import { zeroToRounding } from '../zeroVariance';
import { describeEstimateHistogram } from './plotWords';

/** The histogram's statistics before the first estimates arrive. */
const NOTHING_YET = { count: 0, mean: NaN, sd: NaN, sem: NaN, centers: [], counts: [] };

export function HistogramPanel({
  args,
  N,
  exact,
  makeWorker,
  onN,
}: PanelRunProps & { N: number; onN: (v: number) => void }) {
  const box = useRef<HTMLDivElement>(null);
  const M = 2000;
  const room = useLegendRoom();
  const note = `${M} estimates, each from its own ${N} sample${N === 1 ? '' : 's'} (selected pdf and sequence)`;
  const key = JSON.stringify([args, N]);
  const task = useAutoRun(makeWorker, 'histogram', { ...args, N, M }, { key, box, queue: 'monte-carlo' });
  const est = useThrottled(task.result ?? task.partial, REDRAW_MS, !task.running)?.estimates;
  const stats = useMemo(() => {
    if (!est || !est.length) return null;
    const e = estimateFromTerms(est); // Welford over the finite estimates
    return { mean: e.estimate, sd: e.n > 1 ? Math.sqrt(e.variance) : NaN, count: e.n, sem: e.stderr };
  }, [est]);
  // the estimates' spread is rounding noise (p ∝ f): no bias in standard errors to speak of
  const zero = !!stats && zeroToRounding(stats.sd, stats.mean);
  const bins = useMemo(() => {
    if (!est || !stats) return null;
    const h = histogram(est, 40);
    return { h, centers: arr(h.counts).map((_, k) => 0.5 * (h.edges[k] + h.edges[k + 1])) };
  }, [est, stats]);
  const words = useMemo<PlotWords>(() => {
    const counts = bins ? arr(bins.h.counts) : [];
    const shown = bins && stats ? { ...stats, centers: bins.centers, counts } : NOTHING_YET;
    return {
      description: describeEstimateHistogram({ ...shown, N, exact }),
      table: {
        columns: ['from', 'to', 'estimates'],
        rows: bins && stats ? counts.map((c, k) => [bins.h.edges[k], bins.h.edges[k + 1], c]) : [],
      },
      caption: `Histogram of the independent estimates, each from ${N} samples: bins and counts`,
    };
  }, [bins, stats, N, exact]);
  const data = useMemo<PlotTrace[]>(() => {
    if (!bins || !stats) return [];
    const { h, centers } = bins;
    const ymax = Math.max(...arr(h.counts));
    return [
      {
        type: 'bar',
        x: centers,
        y: arr(h.counts),
        name: `${stats.count} estimates`,
        marker: { color: COLORS[0], opacity: BAR_OPACITY },
        width: (h.edges[1] - h.edges[0]) * 0.95,
      },
      {
        type: 'scatter',
        mode: 'lines',
        x: [exact, exact],
        y: [0, ymax],
        name: `exact ${formatNumber(exact, 8)}`,
        line: { color: REFERENCE, dash: 'dash', width: 2 },
      },
      {
        type: 'scatter',
        mode: 'lines',
        x: [stats.mean, stats.mean],
        y: [0, ymax],
        name: `mean ${formatNumber(stats.mean, 8)}`,
        line: { color: COLORS[1], width: 2 },
      },
    ];
  }, [bins, stats, exact]);
  return (
    <Panel title="Unbiasedness: many independent estimates (Q2 c)" className="mc-plots">
      <div ref={box}>
        <CountField name="hn" value={N} onChange={onN} note={note} />
        <RunBar task={task} label="Estimating…" />
        <div className="readouts">
          <Readout
            id="hist-mean"
            label="mean of the estimates"
            value={stats?.mean ?? null}
            digits={8}
            note={stats ? `± ${formatNumber(stats.sem, 2)} (its standard error)` : undefined}
          />
          <Readout id="hist-sd" label="spread of one estimate (sd)" value={stats?.sd ?? null} digits={4} />
          <Readout
            id="hist-bias"
            label="mean − exact, in standard errors"
            value={stats && !zero ? (stats.mean - exact) / stats.sem : null}
            digits={3}
            note={zero ? 'no spread: every estimate is exact (zero variance)' : undefined}
          />
        </div>
        <DescribedPlot id="estimates-histogram" data={data} height={280 + room / 2} words={words} />
        <p className="mc-note">
          E[⟨I⟩] = ∫ f dx for any valid p: each estimate misses, but their mean lands on the integral (within
          a few standard errors), whatever N is. Only the spread shrinks as N grows.
        </p>
      </div>
    </Panel>
  );
}
