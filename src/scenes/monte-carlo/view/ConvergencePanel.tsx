/** Convergence as N grows: running estimate and |error| log-log with guides and fitted slopes (one run per strategy, in the worker). */
import { useEffect, useMemo, useRef } from 'react';
import { formatNumber, Panel, useThrottled, type PlotTrace } from '../../../ui';
import { useAutoRun } from '../../../workers';
import { atRoundingLevel } from '../zeroVariance';
import { formatCount } from '../../../ui/format';
import type { SeriesData } from '../jobs';
import { REDRAW_MS, useLegendRoom } from './hooks';
import { arr, REFERENCE, RunBar, strategyLine, type PanelRunProps } from './plotStyle';
import { DescribedPlot } from './DescribedPlot';
import { describeSeriesSet, seriesTable } from './plotWords';

export function ConvergencePanel({
  args,
  nMax,
  exact,
  makeWorker,
  present,
  runToken = 0,
}: PanelRunProps & { nMax: number; present: boolean; runToken?: number }) {
  const box = useRef<HTMLDivElement>(null);
  const key = JSON.stringify([args, nMax]);
  const task = useAutoRun(makeWorker, 'convergence', { ...args, nMax }, { key, box, queue: 'monte-carlo' });
  // classroom shortcut (space): run the convergence again
  const rerun = task.run;
  const lastToken = useRef(runToken);
  useEffect(() => {
    if (runToken === lastToken.current) return;
    lastToken.current = runToken;
    rerun();
  }, [runToken, rerun]);
  const cur = useThrottled(task.result ?? task.partial, REDRAW_MS, !task.running);
  const series = useMemo(() => cur?.series ?? [], [cur]);
  const ref = cur?.exact ?? exact;

  const estData = useMemo<PlotTrace[]>(() => {
    const t: PlotTrace[] = series.map((s, i) => ({
      type: 'scatter',
      mode: 'lines',
      x: arr(s.n),
      y: arr(s.estimate),
      name: s.label,
      line: strategyLine(i),
    }));
    if (series.length && Number.isFinite(ref)) {
      const nm = Math.max(1, nMax);
      t.push({
        type: 'scatter',
        mode: 'lines',
        x: [1, nm],
        y: [ref, ref],
        name: `exact ${formatNumber(ref, 8)}`,
        line: { color: REFERENCE, dash: 'dot', width: 2 },
      });
    }
    return t;
  }, [series, ref, nMax]);

  const isExact = (s: SeriesData) => atRoundingLevel(s.absError, ref);
  const exactLabels = series.filter(isExact).map((s) => s.label);
  const errData = useMemo<PlotTrace[]>(() => {
    const t: PlotTrace[] = [];
    series.forEach((s, i) => {
      if (atRoundingLevel(s.absError, ref)) return; // error 0 (rounding level) at every N: no place on a log axis
      t.push({
        type: 'scatter',
        mode: 'lines',
        x: arr(s.n),
        y: arr(s.absError).map((e) => (e > 0 ? e : null)),
        name: `${s.label} (slope ${Number.isFinite(s.slope) ? s.slope.toFixed(2) : '—'})`,
        line: strategyLine(i),
      });
    });
    // guides anchored on the first strategy (uniform · independent): its median |error|·√N
    const s0 = series[0];
    if (s0 && s0.recorded > 2) {
      const scaled = arr(s0.absError)
        .map((e, k) => e * Math.sqrt(s0.n[k]))
        .filter((v) => v > 0)
        .sort((x, y) => x - y);
      const c = scaled[Math.floor(scaled.length / 2)] ?? 1;
      const nm = Math.max(2, nMax);
      t.push({
        type: 'scatter',
        mode: 'lines',
        x: [1, nm],
        y: [c, c / Math.sqrt(nm)],
        name: 'N⁻½ guide',
        line: { color: REFERENCE, dash: 'dash', width: 1.5 },
      });
      t.push({
        type: 'scatter',
        mode: 'lines',
        x: [1, nm],
        y: [c, c / nm],
        name: 'N⁻¹ guide',
        line: { color: REFERENCE, dash: 'dot', width: 1.5 },
      });
    }
    return t;
  }, [series, ref, nMax]);

  // the plots in words and as tables
  const words = useMemo(() => {
    const est = series.map((s) => ({ label: s.label, xs: s.n, ys: s.estimate }));
    const err = series
      .filter((s) => !atRoundingLevel(s.absError, ref))
      .map((s) => ({ label: s.label, xs: s.n, ys: s.absError }));
    const empty = 'No run yet.';
    return {
      est: {
        description: `${describeSeriesSet(est, { xLabel: 'N', yLabel: 'the estimate', empty })} Exact: ${formatNumber(ref, 8)}.`,
        table: seriesTable('N', est),
      },
      err: {
        description: describeSeriesSet(err, { xLabel: 'N', yLabel: '|error|', logLog: true, empty }),
        table: seriesTable(
          'N',
          series.map((s) => ({ label: s.label, xs: s.n, ys: s.absError })),
        ),
      },
    };
  }, [series, ref]);
  const h = (present ? 380 : 300) + useLegendRoom();
  return (
    <Panel title="Convergence as N grows (Q4 d)" className="mc-plots">
      <div ref={box}>
        <RunBar task={task} label={`Running up to N = ${formatCount(nMax)}…`} />
        {cur?.problems.length ? (
          <p className="mc-note">Left out: {cur.problems.map((p) => p.message).join('; ')}</p>
        ) : null}
        <DescribedPlot id="convergence-estimate" data={estData} height={h} words={words.est} />
        <DescribedPlot id="convergence-error" data={errData} height={h} words={words.err} />
        {exactLabels.length ? (
          <p className="mc-note" data-testid="exact-strategies">
            Not drawn on the log axis: {exactLabels.join(', ')} — its error is at rounding level (≤ 10⁻¹³ of
            the integral) at every N: f/p is the same number for every sample (zero variance).
          </p>
        ) : null}
        <p className="mc-note">
          One run’s error jumps around its trend; the slope is fitted to log |error| against log N.
          Independent samples give about −½ (error ∝ N⁻½); stratified and Sobol points do better on a smooth
          f; p ∝ f has no error at all when it is exact (the closed form for (x + c)²) and a tiny one when it
          is tabulated (4096 bins).
        </p>
      </div>
    </Panel>
  );
}
