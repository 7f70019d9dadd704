/**
 * The scene's Plotly views: f with the scaled pdf; convergence (running estimate, |error| log-log
 * with guides and fitted slopes); RMSE over runs with bands and against measured run time; the
 * histogram of independent estimates. Long runs happen in the worker; the plots redraw when a
 * partial result arrives (the worker posts every ~120–150 ms, the hook coalesces to one frame).
 */
import { useEffect, useMemo, useRef, useState, type ReactNode } from 'react';
import { formatNumber, NumberField, Panel, Plot, Readout, useSeenOnce, type PlotTrace } from '../../../ui';
import { useWorkerJob } from '../../../workers';
import { estimateFromTerms } from '../../../core/estimators';
import { histogram } from '../model';
import type { ProblemArgs, RmseData, SeriesData } from '../jobs';

const COLORS = ['#1f5fa8', '#a13f00', '#1d7a3a', '#7b3fa1', '#b8860b', '#d6336c', '#117a8b'];
const arr = (a: ArrayLike<number>) => Array.from(a);
/** Legend above the plot (below, it collides with the x-axis title on narrow screens). */
const LEGEND = { orientation: 'h', x: 0, xanchor: 'left', y: 1.02, yanchor: 'bottom' };
const MARGIN = { l: 60, r: 12, t: 12, b: 48 };

// Layouts are module constants: Plot re-renders whenever its layout object changes identity.
const L_FUNC = { legend: LEGEND, margin: MARGIN, xaxis: { title: { text: 'x' } } };
const L_EST = { xaxis: { type: 'log', title: { text: 'N (samples)' } }, yaxis: { title: { text: 'estimate' } }, legend: LEGEND, margin: MARGIN };
const L_ERR = { xaxis: { type: 'log', title: { text: 'N' } }, yaxis: { type: 'log', title: { text: '|estimate − exact|' }, exponentformat: 'power' }, legend: LEGEND, margin: MARGIN };
const L_RMSE = { xaxis: { type: 'log', title: { text: 'N' } }, yaxis: { type: 'log', title: { text: 'RMSE' }, exponentformat: 'power' }, legend: LEGEND, margin: MARGIN };
const L_TIME = { xaxis: { type: 'log', title: { text: 'ms per estimate (measured here)' } }, yaxis: { type: 'log', title: { text: 'RMSE' }, exponentformat: 'power' }, legend: LEGEND, margin: MARGIN };
const L_HIST = { xaxis: { title: { text: 'estimate ⟨I⟩' } }, yaxis: { title: { text: 'count' } }, bargap: 0, legend: LEGEND, margin: MARGIN };

/** Extra plot height on phones, where the legend above the plot takes several rows. */
function useLegendRoom(): number {
  const q = '(max-width: 600px)';
  const [narrow, setNarrow] = useState(() => typeof window !== 'undefined' && typeof window.matchMedia === 'function' && window.matchMedia(q).matches);
  useEffect(() => {
    if (typeof window.matchMedia !== 'function') return;
    const m = window.matchMedia(q);
    const on = () => setNarrow(m.matches);
    m.addEventListener('change', on);
    return () => m.removeEventListener('change', on);
  }, []);
  return narrow ? 110 : 0;
}

function Heading({ children }: { children: ReactNode }) {
  return <h3 className="mc-plot-title">{children}</h3>;
}

/** f and p × scale on the same axes, with the worked samples marked. */
export function FunctionPlot({ curve, samples, a, b }: { curve: { x: Float64Array; f: Float64Array; p: Float64Array; scale: number }; samples: [number, number][]; a: number; b: number }) {
  const data = useMemo<PlotTrace[]>(() => {
    const t: PlotTrace[] = [{ type: 'scatter', mode: 'lines', x: arr(curve.x), y: arr(curve.f), name: 'f(x)', line: { color: COLORS[0], width: 2.5 } }];
    if (curve.p.some(Number.isFinite)) {
      t.push({ type: 'scatter', mode: 'lines', x: arr(curve.x), y: arr(curve.p), name: `p(x) × ${formatNumber(curve.scale, 3)}`, line: { color: COLORS[1], width: 2, dash: 'dash' } });
    }
    const inside = samples.filter(([x]) => x >= a && x <= b);
    if (inside.length) {
      t.push({ type: 'scatter', mode: 'markers', x: inside.map((s) => s[0]), y: inside.map((s) => s[1]), name: 'samples xᵢ, f(xᵢ)', marker: { color: COLORS[2], size: 9, symbol: 'circle-open', line: { width: 2 } } });
    }
    return t;
  }, [curve, samples, a, b]);
  return <Plot data={data} height={260} ariaLabel="The integrand f(x) and the sampling pdf p(x), scaled to the same height, over [a, b]" layout={L_FUNC} />;
}

/**
 * The value, updated at most every `ms` (a steady redraw rate however fast partial results come),
 * and at once when `immediate` (the final result).
 */
function useThrottled<T>(value: T, ms: number, immediate: boolean): T {
  const [shown, setShown] = useState(value);
  const last = useRef(0);
  const timer = useRef<ReturnType<typeof setTimeout> | undefined>(undefined);
  const latest = useRef(value);
  latest.current = value;
  useEffect(() => {
    const now = performance.now();
    if (immediate || now - last.current >= ms) {
      if (timer.current !== undefined) clearTimeout(timer.current);
      timer.current = undefined;
      last.current = now;
      setShown(value);
    } else if (timer.current === undefined) {
      timer.current = setTimeout(() => {
        timer.current = undefined;
        last.current = performance.now();
        setShown(latest.current);
      }, ms - (now - last.current));
    }
  }, [value, ms, immediate]);
  useEffect(() => () => clearTimeout(timer.current), []);
  return shown;
}

/** Redraw interval of the plots while a run is in progress (ms). */
const REDRAW_MS = 400;

/**
 * Start a worker job when the panel is first seen and whenever its key changes (debounced). The
 * panels share one queue: their runs go one at a time (first come, first served), so the workers
 * never take every core from the page that draws their results (2 cores are common).
 */
function useAutoRun<R, P>(method: string, makeWorker: () => Worker, args: unknown, key: string, box: React.RefObject<HTMLElement | null>) {
  const seen = useSeenOnce(box, '100px');
  return useWorkerJob<R, P>(makeWorker, method, args, { key, enabled: seen, delayMs: 250, queue: 'monte-carlo' });
}

function RunBar({ running, waiting, progress, onCancel, onRun, label }: { running: boolean; waiting: boolean; progress: number; onCancel: () => void; onRun: () => void; label: ReactNode }) {
  return (
    <div className="mc-runbar">
      {waiting && !running ? (
        <span role="status">Waiting for the run above to finish…</span>
      ) : running ? (
        <>
          <progress max={1} value={progress} aria-label="progress" />
          <span role="status">
            {label} {Math.round(progress * 100)} %
          </span>
          <button type="button" onClick={onCancel}>
            Cancel
          </button>
        </>
      ) : (
        <button type="button" onClick={onRun}>
          Run again
        </button>
      )}
    </div>
  );
}

type ConvResult = { series: SeriesData[]; exact: number; problems: string[] };

export function ConvergencePanel({ args, nMax, exact, makeWorker, present, runToken = 0 }: { args: ProblemArgs; nMax: number; exact: number; makeWorker: () => Worker; present: boolean; runToken?: number }) {
  const box = useRef<HTMLDivElement>(null);
  const key = JSON.stringify([args, nMax]);
  const task = useAutoRun<ConvResult, ConvResult>('convergence', makeWorker, { ...args, nMax }, key, box);
  // classroom shortcut (space): run the convergence again
  const rerun = task.run;
  const lastToken = useRef(runToken);
  useEffect(() => {
    if (runToken === lastToken.current) return;
    lastToken.current = runToken;
    rerun();
  }, [runToken, rerun]);
  const cur = useThrottled(task.result ?? task.partial, REDRAW_MS, !task.running);
  const series = cur?.series ?? [];
  const ref = cur?.exact ?? exact;
  const tiny = Math.abs(ref) * 1e-15 || 1e-300;

  const estData = useMemo<PlotTrace[]>(() => {
    const t: PlotTrace[] = series.map((s, i) => ({ type: 'scatter', mode: 'lines', x: arr(s.n), y: arr(s.estimate), name: s.label, line: { color: COLORS[i % COLORS.length], width: 2 } }));
    if (series.length && Number.isFinite(ref)) {
      const nm = Math.max(1, nMax);
      t.push({ type: 'scatter', mode: 'lines', x: [1, nm], y: [ref, ref], name: `exact ${formatNumber(ref, 8)}`, line: { color: '#777', dash: 'dot', width: 2 } });
    }
    return t;
  }, [series, ref, nMax]);

  const isExact = (s: SeriesData) => seriesIsExact(s, tiny);
  const exactLabels = series.filter(isExact).map((s) => s.label);
  const errData = useMemo<PlotTrace[]>(() => {
    const t: PlotTrace[] = [];
    series.forEach((s, i) => {
      if (seriesIsExact(s, tiny)) return; // error 0 (rounding level) at every N: no place on a log axis
      t.push({
        type: 'scatter',
        mode: 'lines',
        x: arr(s.n),
        y: arr(s.absError).map((e) => (e > 0 ? e : null)),
        name: `${s.label} (slope ${Number.isFinite(s.slope) ? s.slope.toFixed(2) : '—'})`,
        line: { color: COLORS[i % COLORS.length], width: 2 },
      });
    });
    // guides anchored on the first strategy (uniform · independent): its median |error|·√N
    const s0 = series[0];
    if (s0 && s0.recorded > 2) {
      const scaled = arr(s0.absError)
        .map((e, k) => e * Math.sqrt(s0.n[k]!))
        .filter((v) => v > 0)
        .sort((x, y) => x - y);
      const c = scaled[Math.floor(scaled.length / 2)] ?? 1;
      const nm = Math.max(2, nMax);
      t.push({ type: 'scatter', mode: 'lines', x: [1, nm], y: [c, c / Math.sqrt(nm)], name: 'N^−1/2 guide', line: { color: '#888', dash: 'dash', width: 1.5 } });
      t.push({ type: 'scatter', mode: 'lines', x: [1, nm], y: [c, c / nm], name: 'N^−1 guide', line: { color: '#888', dash: 'dot', width: 1.5 } });
    }
    return t;
  }, [series, tiny, nMax]);

  const h = (present ? 380 : 300) + useLegendRoom();
  return (
    <Panel title="Convergence as N grows (Q4 d)" className="mc-plots">
      <div ref={box}>
        <RunBar running={task.running} waiting={task.waiting} progress={task.progress} onCancel={task.cancel} onRun={task.run} label={`Running up to N = ${nMax.toLocaleString('en')}…`} />
        {task.error ? <p className="field-error">The run failed: {task.error}</p> : null}
        {cur?.problems.length ? <p className="mc-note">Left out: {cur.problems.join('; ')}</p> : null}
        <Heading>Running estimate</Heading>
        <Plot
          data={estData}
          height={h}
          ariaLabel="Running estimate against the number of samples N, on a log axis, for several strategies, with the exact value"
          layout={L_EST}
        />
        <Heading>|error| of one run, log-log, with N^−½ and N^−1 guides</Heading>
        <Plot
          data={errData}
          height={h}
          ariaLabel="Absolute error against N on log-log axes, with N^-1/2 and N^-1 guide lines and fitted slopes"
          layout={L_ERR}
        />
        {exactLabels.length ? (
          <p className="mc-note" data-testid="exact-strategies">
            Not drawn on the log axis: {exactLabels.join(', ')} — its error is at rounding level (≤ 10⁻¹³ of the integral) at every N: f/p is the same number for every sample (zero
            variance).
          </p>
        ) : null}
        <p className="mc-note">
          One run’s error jumps around its trend; the slope is fitted to log |error| against log N. Independent samples give about −½ (error ∝ N^−½); stratified and Sobol points
          do better on a smooth f; p ∝ f has no error at all when it is exact (the closed form for (x + c)²) and a tiny one when it is tabulated (4096 bins).
        </p>
      </div>
    </Panel>
  );
}

type RmseResult = { rmse: RmseData[]; exact?: number; problems?: string[] };

export function RmsePanel({ args, nMax, runs, exact, makeWorker, onRuns }: { args: ProblemArgs; nMax: number; runs: number; exact: number; makeWorker: () => Worker; onRuns: (r: number) => void }) {
  const box = useRef<HTMLDivElement>(null);
  const key = JSON.stringify([args, nMax, runs]);
  const task = useAutoRun<RmseResult, RmseResult>('rmse', makeWorker, { ...args, nMax, runs }, key, box);
  const cur = useThrottled(task.result ?? task.partial, REDRAW_MS, !task.running);
  const rm = cur?.rmse ?? [];
  const tiny = Math.abs(exact) * 1e-15 || 1e-300;
  const rmExactLabels = rm.filter((s) => rmseIsExact(s, tiny)).map((s) => s.label);

  const rmseData = useMemo<PlotTrace[]>(() => {
    const t: PlotTrace[] = [];
    rm.forEach((s, i) => {
      if (rmseIsExact(s, tiny)) return;
      const c = COLORS[i % COLORS.length]!;
      const n = arr(s.n);
      t.push({ type: 'scatter', mode: 'lines', x: n, y: clampArr(s.hi), line: { width: 0, color: c }, hoverinfo: 'skip', showlegend: false, legendgroup: s.label });
      t.push({ type: 'scatter', mode: 'lines', x: n, y: clampArr(s.lo), line: { width: 0, color: c }, fill: 'tonexty', fillcolor: hexA(c, 0.15), hoverinfo: 'skip', showlegend: false, legendgroup: s.label });
      t.push({
        type: 'scatter',
        mode: 'lines+markers',
        x: n,
        y: clampArr(s.rmse),
        name: `${s.label} (slope ${Number.isFinite(s.slope) ? s.slope.toFixed(2) : '—'})`,
        line: { color: c, width: 2 },
        marker: { size: 5 },
        legendgroup: s.label,
      });
    });
    return t;
  }, [rm, tiny]);

  const timeData = useMemo<PlotTrace[]>(
    () =>
      rm.flatMap((s, i) => {
        if (rmseIsExact(s, tiny)) return [];
        const keep = arr(s.n).map((_, k) => k).filter((k) => s.timeMs[k]! > 0 && Number.isFinite(s.rmse[k]!));
        return {
          type: 'scatter',
          mode: 'lines+markers',
          x: keep.map((k) => s.timeMs[k]),
          y: keep.map((k) => s.rmse[k]),
          text: keep.map((k) => `N = ${s.n[k]}`),
          name: s.label,
          line: { color: COLORS[i % COLORS.length], width: 2 },
          marker: { size: 5 },
        };
      }),
    [rm, tiny],
  );

  const runsDone = rm[0]?.runs ?? 0;
  const h = 300 + useLegendRoom();
  return (
    <Panel title="RMSE over independent runs, and against run time" className="mc-plots">
      <div ref={box}>
        <div className="mc-inline">
          <NumberField label="runs" value={runs} min={4} max={256} step={1} onChange={(v) => onRuns(Math.round(v))} testId="runs-input" />
          <span className="mc-note">
            {runsDone} run{runsDone === 1 ? '' : 's'} per strategy so far, N up to {nMax.toLocaleString('en')}
          </span>
        </div>
        <RunBar running={task.running} waiting={task.waiting} progress={task.progress} onCancel={task.cancel} onRun={task.run} label="Independent runs…" />
        {task.error ? <p className="field-error">The run failed: {task.error}</p> : null}
        <Heading>RMSE over the runs (band: 10–90 % of |error|)</Heading>
        <Plot
          data={rmseData}
          height={h}
          ariaLabel="Root mean square error over independent runs against N, log-log, with bands from the 10th to the 90th percentile of the absolute error"
          layout={L_RMSE}
        />
        <Heading>Accuracy per millisecond: RMSE against run time</Heading>
        <Plot
          data={timeData}
          height={h}
          ariaLabel="RMSE against the measured wall-clock time of one estimate, log-log, per strategy"
          layout={L_TIME}
        />
        {rmExactLabels.length ? <p className="mc-note">Not drawn: {rmExactLabels.join(', ')} (RMSE at rounding level: zero variance).</p> : null}
        <p className="mc-note">
          Run time of one N-sample estimate = N × the cost per sample measured over all runs in a worker in your browser (set-up such as tabulating a pdf is not
          counted). A curve further down and to the left buys more accuracy per millisecond.
        </p>
      </div>
    </Panel>
  );
}

type HistResult = { estimates: Float64Array; exact?: number };

export function HistogramPanel({ args, N, exact, makeWorker, onN }: { args: ProblemArgs; N: number; exact: number; makeWorker: () => Worker; onN: (v: number) => void }) {
  const box = useRef<HTMLDivElement>(null);
  const M = 2000;
  const room = useLegendRoom();
  const key = JSON.stringify([args, N]);
  const task = useAutoRun<HistResult, HistResult>('histogram', makeWorker, { ...args, N, M }, key, box);
  const est = useThrottled(task.result ?? task.partial, REDRAW_MS, !task.running)?.estimates;
  const stats = useMemo(() => {
    if (!est || !est.length) return null;
    const e = estimateFromTerms(est); // Welford over the finite estimates
    return { mean: e.estimate, sd: e.n > 1 ? Math.sqrt(e.variance) : NaN, count: e.n, sem: e.stderr };
  }, [est]);
  const data = useMemo<PlotTrace[]>(() => {
    if (!est || !stats) return [];
    const h = histogram(est, 40);
    const centers = arr(h.counts).map((_, k) => 0.5 * (h.edges[k]! + h.edges[k + 1]!));
    const ymax = Math.max(...arr(h.counts));
    return [
      { type: 'bar', x: centers, y: arr(h.counts), name: `${stats.count} estimates`, marker: { color: COLORS[0], opacity: 0.75 }, width: (h.edges[1]! - h.edges[0]!) * 0.95 },
      { type: 'scatter', mode: 'lines', x: [exact, exact], y: [0, ymax], name: `exact ${formatNumber(exact, 8)}`, line: { color: '#444', dash: 'dash', width: 2 } },
      { type: 'scatter', mode: 'lines', x: [stats.mean, stats.mean], y: [0, ymax], name: `mean ${formatNumber(stats.mean, 8)}`, line: { color: COLORS[1], width: 2 } },
    ];
  }, [est, stats, exact]);
  return (
    <Panel title="Unbiasedness: many independent estimates (Q2 c)" className="mc-plots">
      <div ref={box}>
        <div className="mc-inline">
          <NumberField label="samples per estimate" value={N} min={1} max={10000} step={1} onChange={(v) => onN(Math.round(v))} testId="hn-input" />
          <span className="mc-note">{M} estimates, each from its own {N} sample{N === 1 ? '' : 's'} (selected pdf and sequence)</span>
        </div>
        <RunBar running={task.running} waiting={task.waiting} progress={task.progress} onCancel={task.cancel} onRun={task.run} label="Estimating…" />
        {task.error ? <p className="field-error">The run failed: {task.error}</p> : null}
        <div className="readouts">
          <Readout id="hist-mean" label="mean of the estimates" value={stats?.mean ?? null} digits={8} note={stats ? `± ${formatNumber(stats.sem, 2)} (its standard error)` : undefined} />
          <Readout id="hist-sd" label="spread of one estimate (sd)" value={stats?.sd ?? null} digits={4} />
          <Readout
            id="hist-bias"
            label="mean − exact, in standard errors"
            value={stats && stats.sd > 1e-12 * Math.abs(exact) ? (stats.mean - exact) / stats.sem : null}
            digits={3}
            note={stats && !(stats.sd > 1e-12 * Math.abs(exact)) ? 'no spread: every estimate is exact (zero variance)' : undefined}
          />
        </div>
        <Plot
          data={data}
          height={280 + room / 2}
          ariaLabel="Histogram of many independent estimates at fixed N, with their mean and the exact integral"
          layout={L_HIST}
        />
        <p className="mc-note">
          E[⟨I⟩] = ∫ f dx for any valid p: each estimate misses, but their mean lands on the integral (within a few standard errors), whatever N is. Only the spread shrinks as N grows.
        </p>
      </div>
    </Panel>
  );
}

/** Positive finite values, null elsewhere (a gap on a log axis). */
const clampArr = (a: Float64Array) => arr(a).map((v) => (Number.isFinite(v) && v > 0 ? v : null));
/** Error at rounding level (≤ 100 × tiny) at every recorded N: f/p is constant (zero variance). */
const seriesIsExact = (s: SeriesData, tiny: number) => s.recorded > 0 && Math.max(...arr(s.absError)) <= tiny * 100;
const rmseIsExact = (s: RmseData, tiny: number) => s.runs > 0 && Math.max(...arr(s.rmse).filter(Number.isFinite)) <= tiny * 100;

function hexA(hex: string, a: number): string {
  const v = parseInt(hex.slice(1), 16);
  return `rgba(${(v >> 16) & 255}, ${(v >> 8) & 255}, ${v & 255}, ${a})`;
}
