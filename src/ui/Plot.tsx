import { useEffect, useRef, useState } from 'react';
import { useSeenOnce } from './useInView';

type PlotlyModule = (typeof import('plotly.js-cartesian-dist-min'))['default'];
let plotlyPromise: Promise<PlotlyModule> | null = null;

/** Load plotly.js (cartesian bundle: scatter, bar, histogram, heatmap, histogram2d, contour) once. */
export function loadPlotly(): Promise<PlotlyModule> {
  if (!plotlyPromise) {
    plotlyPromise = import('plotly.js-cartesian-dist-min').then((m) => ((m as unknown as { default?: PlotlyModule }).default ?? (m as unknown as PlotlyModule)));
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
  /** What the plot shows, for screen readers (the plot itself is not accessible). */
  ariaLabel: string;
  testId?: string;
}

function touchOnly(): boolean {
  return typeof window.matchMedia === 'function' && window.matchMedia('(hover: none) and (pointer: coarse)').matches;
}

function themeColors() {
  const cs = getComputedStyle(document.documentElement);
  return {
    fg: cs.getPropertyValue('--fg').trim() || '#222',
    grid: cs.getPropertyValue('--grid').trim() || '#ddd',
    font: cs.getPropertyValue('--plot-font-size').trim() || '13',
  };
}

/**
 * A lazy Plotly plot: plotly.js loads only when the plot scrolls near the viewport; updates go
 * through Plotly.react in an effect (cheap diffing); the plot is purged on unmount.
 */
export function Plot({ data, layout, height = 280, ariaLabel, testId }: PlotProps) {
  const box = useRef<HTMLDivElement>(null);
  const el = useRef<HTMLDivElement>(null);
  const seen = useSeenOnce(box);
  const [plotly, setPlotly] = useState<PlotlyModule | null>(null);
  const [failed, setFailed] = useState(false);
  const themeKey = typeof document !== 'undefined' ? `${document.documentElement.dataset.theme}-${document.documentElement.classList.contains('present')}` : '';

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
  const layoutRef = useRef(layout);
  layoutRef.current = layout;

  useEffect(() => {
    if (!plotly || !el.current) return;
    const layout = layoutRef.current;
    const c = themeColors();
    // mathematical axes: powers of ten (1×10⁻⁶), never SI prefixes (1µ)
    const axis = { gridcolor: c.grid, zerolinecolor: c.grid, linecolor: c.grid, automargin: true, exponentformat: 'power' };
    const base: PlotLayout = {
      height,
      margin: { l: 56, r: 16, t: 28, b: 44 },
      paper_bgcolor: 'rgba(0,0,0,0)',
      plot_bgcolor: 'rgba(0,0,0,0)',
      font: { color: c.fg, size: Number(c.font) || 13 },
      legend: { orientation: 'h', y: -0.25 },
      xaxis: axis,
      yaxis: axis,
    };
    const merged: PlotLayout = { ...base, ...layout };
    for (const k of ['xaxis', 'yaxis', 'xaxis2', 'yaxis2']) {
      if (layout && layout[k]) merged[k] = { ...axis, ...(layout[k] as object) };
    }
    plotly.react(el.current, data, merged, {
      responsive: true,
      displaylogo: false,
      // on touch screens the mode bar would sit over titles and legends with no hover to hide it
      displayModeBar: touchOnly() ? false : 'hover',
      modeBarButtonsToRemove: ['lasso2d', 'select2d'],
    }).catch(() => setFailed(true));
  }, [plotly, data, layoutKey, height, themeKey]);

  useEffect(() => {
    const node = el.current;
    return () => {
      if (node && plotly) plotly.purge(node);
    };
  }, [plotly]);

  return (
    <figure className="plot" ref={box} style={{ minHeight: height }} aria-label={ariaLabel} data-testid={testId}>
      {failed ? <p className="plot-placeholder">The plot could not be drawn.</p> : null}
      {!plotly && !failed ? <p className="plot-placeholder">Loading plot…</p> : null}
      <div ref={el} className="plot-canvas" />
    </figure>
  );
}
