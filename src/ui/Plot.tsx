import { useEffect, useId, useMemo, useRef, useState } from 'react';
import { observeVisibility, touchOnly, useSeenOnce } from './useInView';
import { resolveTraceColors } from './palette';
import { isPresent } from './pageKeys';
import './plot.css';
import { runChunked } from './chunked';
import { PLOT_CONFIG, PLOT_LEGEND } from './plotConfig';

type PlotlyModule = (typeof import('plotly.js-cartesian-dist-min'))['default'];
let plotlyPromise: Promise<PlotlyModule> | null = null;

/** Load plotly.js (cartesian bundle: scatter, bar, histogram, heatmap, histogram2d, contour) once. */
export function loadPlotly(): Promise<PlotlyModule> {
  if (!plotlyPromise) {
    plotlyPromise = import('plotly.js-cartesian-dist-min').then(
      (m) => (m as unknown as { default?: PlotlyModule }).default ?? (m as unknown as PlotlyModule),
    );
  }
  return plotlyPromise;
}

/** A Plotly trace: plain objects as Plotly takes them. */
export type PlotTrace = Record<string, unknown>;
export type PlotLayout = Record<string, unknown>;

export interface PlotProps {
  data: PlotTrace[];
  layout?: PlotLayout;
  height?: number;
  /** The plot's accessible name (older name of `label`; `label` wins when both are given). */
  ariaLabel?: string;
  /** The plot's accessible name: what it plots ("|error| against N"). */
  label?: string;
  /**
   * What its data shows, for readers who cannot see it (build it with summarizeSeries): the
   * plot's aria-describedby text, visually hidden. Plotly's own SVG is not accessible.
   */
  description?: string;
  testId?: string;
}

/** Largest magnitude Plotly draws: beyond it its axis arithmetic overflows to NaN paths. */
const PLOT_MAX_ABS = 1e100;
/**
 * Smallest non-zero magnitude Plotly draws: below it (subnormals included) its axis arithmetic
 * underflows ("Something went wrong with axis scaling"), so such values are drawn as 0.
 */
const PLOT_MIN_ABS = 1e-100;

/**
 * Replace infinite or astronomically large numbers (NaN is already a gap to Plotly) in the traces'
 * x / y / z arrays by null (a gap), and non-zero numbers too small for Plotly's axes by 0, so
 * Plotly never draws a NaN path or fails to scale an axis; returns the traces and how many values
 * were left out (`dropped`) or drawn as 0 (`flushed`).
 */
export function sanitizeTraces(data: PlotTrace[]): { data: PlotTrace[]; dropped: number; flushed: number } {
  let dropped = 0;
  let flushed = 0;
  const tiny = (v: number) => v !== 0 && Math.abs(v) < PLOT_MIN_ABS;
  const clean = (v: unknown): unknown => {
    if (typeof v === 'number' && Math.abs(v) > PLOT_MAX_ABS) {
      dropped++;
      return null;
    }
    if (typeof v === 'number' && tiny(v)) {
      flushed++;
      return 0;
    }
    return v;
  };
  const out = data.map((t) => {
    let copy: PlotTrace | null = null;
    for (const k of ['x', 'y', 'z'] as const) {
      const a = t[k];
      if (!Array.isArray(a) && !ArrayBuffer.isView(a)) continue;
      const arr = Array.from(a as ArrayLike<unknown>);
      let bad = false;
      for (const v of arr)
        if (typeof v === 'number' ? Math.abs(v) > PLOT_MAX_ABS || tiny(v) : Array.isArray(v)) bad = true;
      if (!bad) continue;
      copy ??= { ...t };
      copy[k] = arr.map((v) => (Array.isArray(v) ? v.map(clean) : clean(v)));
    }
    return copy ?? t;
  });
  return { data: out, dropped, flushed };
}

function themeColors() {
  const cs = getComputedStyle(document.documentElement);
  return {
    fg: cs.getPropertyValue('--fg').trim() || '#222',
    grid: cs.getPropertyValue('--grid').trim() || '#ddd',
    font: cs.getPropertyValue('--plot-font-size').trim() || '13',
  };
}

/** Classroom mode: the smallest tick label size (px), readable from the back of a lecture hall. */
export const PRESENT_TICK_PX = 18;

/**
 * Raises every axis's tick labels to {@link PRESENT_TICK_PX} (a layout's own larger size stays). A
 * log axis labels the digits between its decades ("2", "5") at 3/4 of its tick size, so its tick
 * size is 4/3 of that.
 */
function presentTicks(layout: PlotLayout): void {
  for (const [k, v] of Object.entries(layout)) {
    if (!/^[xy]axis\d*$/.test(k) || !v || typeof v !== 'object') continue;
    const ax = v as { tickfont?: { size?: unknown }; type?: unknown };
    const size = typeof ax.tickfont?.size === 'number' ? ax.tickfont.size : 0;
    const least = ax.type === 'log' ? Math.ceil((PRESENT_TICK_PX * 4) / 3) : PRESENT_TICK_PX;
    layout[k] = { ...v, tickfont: { ...ax.tickfont, size: Math.max(size, least) } };
  }
}

/** How far outside the viewport a plot still redraws on a change: one screen above and below. */
const NEAR_VIEW = '100% 0px';

/**
 * A lazy Plotly plot: plotly.js loads only when the plot scrolls near the viewport; updates go
 * through Plotly.react in an effect (cheap diffing); the plot is purged on unmount. A plot far off
 * screen does not redraw on every change (a storm of changes would redraw every plot of the page
 * each time): it draws its latest data when it comes back near the viewport.
 */
export function Plot({ data, layout, height = 280, ariaLabel, label, description, testId }: PlotProps) {
  const descId = `${useId()}-description`;
  const box = useRef<HTMLDivElement>(null);
  const el = useRef<HTMLDivElement>(null);
  const seen = useSeenOnce(box);
  const [plotly, setPlotly] = useState<PlotlyModule | null>(null);
  const [failed, setFailed] = useState(false);
  const [near, setNear] = useState(true);
  useEffect(() => {
    const node = box.current;
    return node ? observeVisibility(node, setNear, NEAR_VIEW) : undefined;
  }, []);
  /** The inputs of the last redraw that ran (a plot back in view with the same ones draws nothing). */
  const drawnFor = useRef<readonly unknown[] | null>(null);
  const themeKey =
    typeof document !== 'undefined'
      ? `${document.documentElement.dataset.theme}-${document.documentElement.classList.contains('present')}`
      : '';

  useEffect(() => {
    if (!seen) return;
    let alive = true;
    loadPlotly().then(
      (p) => alive && setPlotly(() => p),
      () => alive && setFailed(true),
    );
    return () => {
      alive = false;
    };
  }, [seen]);

  // Layouts are small: compare them by content, so an inline `layout={{…}}` does not make Plotly
  // redraw on every render of the parent. Data is compared by identity (memoise it).
  const layoutKey = layout ? JSON.stringify(layout) : '';
  const clean = useMemo(() => sanitizeTraces(data), [data]);
  const layoutRef = useRef(layout);
  layoutRef.current = layout;

  useEffect(() => {
    if (!plotly || !el.current || !near) return;
    const inputs = [plotly, clean, layoutKey, height, themeKey] as const;
    if (drawnFor.current?.every((x, i) => x === inputs[i])) return;
    const layout = layoutRef.current;
    const c = themeColors();
    // mathematical axes: powers of ten (1×10⁻⁶), never SI prefixes (1µ)
    const axis = {
      gridcolor: c.grid,
      zerolinecolor: c.grid,
      linecolor: c.grid,
      automargin: true,
      exponentformat: 'power',
    };
    const base: PlotLayout = {
      height,
      margin: { l: 56, r: 16, t: 28, b: 44 },
      paper_bgcolor: 'rgba(0,0,0,0)',
      plot_bgcolor: 'rgba(0,0,0,0)',
      font: { color: c.fg, size: Number(c.font) || 13 },
      legend: PLOT_LEGEND,
      xaxis: axis,
      yaxis: axis,
    };
    const merged: PlotLayout = { ...base, ...layout };
    for (const k of ['xaxis', 'yaxis', 'xaxis2', 'yaxis2']) {
      if (layout && layout[k]) merged[k] = { ...axis, ...(layout[k] as object) };
    }
    if (isPresent()) presentTicks(merged);
    // Each plot's redraw is a job of its own (./chunked): the plots that one change updates
    // together (a scene has up to four) are drawn in separate tasks, not in one long one.
    const node = el.current;
    let settle = () => {};
    let started = false;
    pending.current = new Promise<void>((resolve) => (settle = resolve));
    const cancel = runChunked(() => {
      started = true;
      drawnFor.current = inputs;
      plotly
        .react(node, resolveTraceColors(clean.data), resolveTraceColors(merged), {
          ...PLOT_CONFIG,
          // on touch screens the mode bar would sit over titles and legends with no hover to hide it
          displayModeBar: touchOnly() ? false : 'hover',
        })
        .catch(() => setFailed(true))
        .finally(settle);
    });
    return () => {
      // a newer redraw replaces one not started yet; one under way settles by itself
      cancel();
      if (!started) settle();
    };
  }, [plotly, clean, layoutKey, height, themeKey, near]);

  // Purge only after the last react() has settled and its follow-up redraws (Plotly's auto-margin
  // pass) have run: purging a plot mid-update makes Plotly throw "e.emit is not a function" from
  // an internal promise (seen when a control change unmounts a plot while it redraws).
  const pending = useRef<Promise<unknown> | null>(null);
  useEffect(() => {
    const node = el.current;
    return () => {
      if (!node || !plotly) return;
      const purge = () => setTimeout(() => plotly.purge(node), 300);
      if (pending.current) void pending.current.then(purge, purge);
      else purge();
    };
  }, [plotly]);

  return (
    <figure
      className="plot"
      ref={box}
      style={{ minHeight: height }}
      role="group"
      aria-label={label ?? ariaLabel}
      aria-describedby={description ? descId : undefined}
      data-testid={testId}
    >
      {description ? (
        <p id={descId} className="sr-only" data-testid={testId ? `${testId}-description` : undefined}>
          {description}
        </p>
      ) : null}
      {failed ? <p className="plot-placeholder">The plot could not be drawn.</p> : null}
      {!plotly && !failed ? <p className="plot-placeholder">Loading plot…</p> : null}
      <div ref={el} className="plot-canvas" />
      {clean.dropped > 0 ? (
        <figcaption className="small" data-testid="plot-dropped">
          {clean.dropped} value{clean.dropped === 1 ? '' : 's'} too large to draw (±∞ or beyond ±10¹⁰⁰) left
          out of this plot.
        </figcaption>
      ) : null}
      {clean.flushed > 0 ? (
        <figcaption className="small" data-testid="plot-flushed">
          {clean.flushed} value{clean.flushed === 1 ? '' : 's'} closer to 0 than 10⁻¹⁰⁰ drawn as 0 (too small
          for the plot&rsquo;s axes).
        </figcaption>
      ) : null}
    </figure>
  );
}
