/**
 * The animation's convergence figure: the running estimate after k samples with its ±2σ band
 * (σ = s/√k, the standard error the estimator reports), against k on a log axis, and the reference
 * as a dashed line. The curve and band for all samples are built once per run (memoised on the
 * run); at position t only a clip rectangle and the marker move (written directly, see drawRef),
 * so a frame costs next to nothing.
 */
import { memo, useLayoutEffect, useMemo, useRef } from 'react';
import { formatNumber } from '../../../core/format';
import { RunningEstimatePlot } from '../../../ui/RunningEstimatePlot';
import type { SampleRun } from '../animation';

const W = 420;
const H = 230;
// room for the tick labels at the larger phone type (19 px): "0.0602" on the left, half of "1000" on the right
const M = { l: 78, r: 24, t: 14, b: 40 };

/** Tick labels and the label's figures: three significant digits. */
const fmt = (x: number): string => formatNumber(x, 3);

interface Geometry {
  xOf: (k: number) => number;
  yOf: (v: number) => number;
  line: string;
  band: string;
  yTicks: number[];
  xTicks: number[];
}

/**
 * Scales and paths of the plot. A non-finite running mean (a degenerate configuration can give
 * NaN or ±∞ samples) sets no scale, breaks the line and the band there, and is drawn nowhere:
 * an SVG attribute must never read "NaN".
 */
export function geometry(run: SampleRun, reference: number): Geometry {
  const n = run.count;
  const xOf = (k: number) => M.l + ((W - M.l - M.r) * Math.log(Math.max(1, k))) / Math.log(Math.max(2, n));
  // y range: the band from 8 samples on (earlier σ is too rough to set a scale), and the reference.
  let lo = Infinity,
    hi = -Infinity;
  const from = Math.min(n, 8) - 1;
  for (let i = Math.max(0, from); i < n; i++) {
    const m = run.mean[i],
      s = Number.isFinite(run.stderr[i]) ? run.stderr[i] : 0;
    if (!Number.isFinite(m)) continue;
    lo = Math.min(lo, m - 2 * s);
    hi = Math.max(hi, m + 2 * s);
  }
  if (Number.isFinite(reference)) {
    lo = Math.min(lo, reference);
    hi = Math.max(hi, reference);
  }
  if (!(hi > lo)) {
    const c = Number.isFinite(lo) ? lo : 0;
    lo = c - Math.max(1e-12, Math.abs(c) * 0.1);
    hi = c + Math.max(1e-12, Math.abs(c) * 0.1);
  }
  const pad = 0.08 * (hi - lo);
  lo -= pad;
  hi += pad;
  const yOf = (v: number) => {
    // (a range past the largest double, or a NaN, lands mid-plot instead of in an attribute)
    const f = (hi - Math.min(hi, Math.max(lo, v))) / (hi - lo);
    return M.t + (H - M.t - M.b) * (Number.isFinite(f) ? f : 0.5);
  };
  let line = '';
  let upper = '';
  let lower = '';
  let pen = false; // whether the line is drawing (a non-finite mean lifts it)
  for (let i = 0; i < n; i++) {
    const x = xOf(i + 1).toFixed(1);
    const m = run.mean[i];
    if (!Number.isFinite(m)) {
      pen = false;
      continue;
    }
    line += `${pen ? 'L' : 'M'}${x},${yOf(m).toFixed(1)}`;
    pen = true;
    const s = run.stderr[i];
    if (i >= 1 && Number.isFinite(s) && Number.isFinite(m + 2 * s) && Number.isFinite(m - 2 * s)) {
      upper += `${upper ? 'L' : 'M'}${x},${yOf(m + 2 * s).toFixed(1)}`;
      lower = `L${x},${yOf(m - 2 * s).toFixed(1)}` + lower;
    }
  }
  const band = upper ? `${upper}${lower}Z` : '';
  const yTicks = [lo + pad, (lo + hi) / 2, hi - pad];
  const xTicks: number[] = [];
  for (let k = 1; k <= n; k *= 10) xTicks.push(k);
  // the end, unless it would crowd the last power of ten
  if (n / xTicks[xTicks.length - 1] >= 2.5) xTicks.push(n);
  return { xOf, yOf, line, band, yTicks, xTicks };
}

/**
 * The running estimate at k samples. With `drawRef`, the moving parts (the clip, the marker, the
 * label) are written directly for another k (per animation frame, without a React render); `k` is
 * then the position of the component's last render.
 */
export const RunningEstimate = memo(function RunningEstimate({
  run,
  reference,
  k,
  drawRef,
}: {
  run: SampleRun;
  reference: number;
  k: number;
  drawRef?: { current: ((k: number, text: boolean) => void) | null };
}) {
  const g = useMemo(() => geometry(run, reference), [run, reference]);
  const svg = useRef<SVGSVGElement>(null);
  const shown = useRef(k);
  const label = (kk: number) => {
    const est = kk > 0 ? run.mean[kk - 1] : NaN;
    return `Running estimate after ${kk} of ${run.count} samples: ${fmt(est)}; reference ${fmt(reference)}. The shaded band is ±2 standard errors.`;
  };
  const draw = (kk: number, text: boolean) => {
    shown.current = kk;
    const el = svg.current;
    if (!el) return;
    const xk = g.xOf(Math.max(1, kk));
    const est = kk > 0 && kk <= run.count ? run.mean[kk - 1] : NaN;
    el.querySelector('clipPath rect')?.setAttribute('width', String(kk > 0 ? xk + 0.5 : 0));
    const dot = el.querySelector('circle.al-run-dot');
    if (dot) {
      if (kk > 0 && Number.isFinite(est)) {
        dot.removeAttribute('display');
        dot.setAttribute('cx', String(xk));
        dot.setAttribute('cy', String(g.yOf(est)));
      } else dot.setAttribute('display', 'none');
    }
    if (text) el.setAttribute('aria-label', label(kk));
  };
  if (drawRef) drawRef.current = draw;
  else shown.current = k;
  useLayoutEffect(() => draw(shown.current, true));
  const ticks = (vs: number[], at: (v: number) => number, text: (v: number) => string) =>
    vs.map((v) => [at(v), text(v)] as const);
  return (
    <RunningEstimatePlot
      svgRef={svg}
      className="al-running"
      width={W}
      height={H}
      margin={M}
      xTicks={ticks(g.xTicks, g.xOf, String)}
      yTicks={ticks(g.yTicks, g.yOf, fmt)}
      xLabel="samples k (log scale)"
      exactY={Number.isFinite(reference) ? g.yOf(reference) : null}
      band={g.band}
      line={g.line}
      clipWidth={0}
      ariaLabel={label(k)}
      testId="al-running"
    >
      <circle r={4} className="al-run-dot" display="none" />
    </RunningEstimatePlot>
  );
});
