import { useEffect, useId, useMemo, useRef, useState, type PointerEvent as ReactPointerEvent } from 'react';
import { observeVisibility, touchOnly, useSeenOnce } from './useInView';
import { resolveColor } from './palette';
import { usePresent } from './pageKeys';
import { useWidth } from './useWidth';
import { downloadFile } from './download';
import type { ChartModel, View } from './chart/model';
import type { Rect } from './chart/marks';
import type { ChartColors, Readout } from './chart/ChartSvg';
import type { ChartLayout, ChartTrace } from './chart/types';
import { PLOT_TOOLS, type PlotTool } from './plotTools';
import './plot.css';

/** A trace, in the shape of Plotly's (./chart/types). */
export type PlotTrace = ChartTrace;
export type PlotLayout = ChartLayout;

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
   * plot's aria-describedby text, visually hidden. The drawing itself is hidden from assistive
   * technology.
   */
  description?: string;
  testId?: string;
}

/** Largest magnitude drawn: beyond it a value is a gap (no axis spans ±10¹⁰⁰ meaningfully). */
const PLOT_MAX_ABS = 1e100;
/** Smallest non-zero magnitude drawn as itself: below it (subnormals included) a value is drawn as 0. */
const PLOT_MIN_ABS = 1e-100;

/**
 * Replace infinite or astronomically large numbers (NaN is already a gap) in the traces' x / y / z
 * arrays by null (a gap), and non-zero numbers too small for an axis by 0; returns the traces and
 * how many values were left out (`dropped`) or drawn as 0 (`flushed`).
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
    let copy: Record<string, unknown> | null = null;
    for (const k of ['x', 'y', 'z'] as const) {
      const a = (t as unknown as Record<string, unknown>)[k];
      if (!Array.isArray(a) && !ArrayBuffer.isView(a)) continue;
      const arr = Array.from(a as ArrayLike<unknown>);
      let bad = false;
      for (const v of arr)
        if (typeof v === 'number' ? Math.abs(v) > PLOT_MAX_ABS || tiny(v) : Array.isArray(v)) bad = true;
      if (!bad) continue;
      copy ??= { ...t };
      copy[k] = arr.map((v) => (Array.isArray(v) ? v.map(clean) : clean(v)));
    }
    return (copy ?? t) as PlotTrace;
  });
  return { data: out, dropped, flushed };
}

type ChartModule = typeof import('./chart/draw');
let chartModule: Promise<ChartModule> | null = null;

/** The chart's code (./chart/draw), loaded once, when a page's first plot comes near the screen. */
export function loadChart(): Promise<ChartModule> {
  chartModule ??= import('./chart/draw');
  return chartModule;
}

/** Classroom mode: the smallest tick label size (px), readable from the back of a lecture hall. */
export const PRESENT_TICK_PX = 18;

/**
 * The value as first given, until one that differs in content (its JSON) comes: a stable identity
 * for a small object a parent writes inline on every render.
 */
function useSameByContent<T>(value: T): T {
  const key = value === undefined ? '' : JSON.stringify(value);
  const kept = useRef({ key, value });
  if (kept.current.key !== key) kept.current = { key, value };
  return kept.current.value;
}

/** Width (px) of one tool button and its gap (plot.css). */
const TOOL_WIDTH = 30;

/** How far outside the viewport a plot still redraws on a change: one screen above and below. */
const NEAR_VIEW = '100% 0px';

let measureCtx: CanvasRenderingContext2D | null | undefined;
/** Width of text in the page's font: a canvas measures it; without one, an average glyph width. */
function measurer(family: string): (text: string, size: number) => number {
  if (measureCtx === undefined)
    measureCtx = typeof document !== 'undefined' ? document.createElement('canvas').getContext('2d') : null;
  const ctx = measureCtx;
  const cache = new Map<string, number>();
  return (text, size) => {
    const key = `${size}|${text}`;
    let w = cache.get(key);
    if (w === undefined) {
      if (ctx) {
        ctx.font = `${size}px ${family}`;
        w = ctx.measureText(text).width;
      } else w = text.length * size * 0.56;
      cache.set(key, w);
    }
    return w;
  };
}

function themeColors(): ChartColors {
  const cs = getComputedStyle(document.documentElement);
  const v = (name: string, fallback: string) => cs.getPropertyValue(name).trim() || fallback;
  const cache = new Map<string, string>();
  return {
    fg: v('--fg', '#222'),
    muted: v('--muted', '#555'),
    grid: v('--grid', '#ddd'),
    bg: v('--bg', '#fff'),
    paint: (c) => {
      if (!c.startsWith('var(')) return c;
      let r = cache.get(c);
      if (r === undefined) cache.set(c, (r = resolveColor(c)));
      return r;
    },
  };
}

/** The view `k` times narrower (k < 1: wider) about its middle, on both axes. */
function zoomed(m: ChartModel, k: number): View {
  const scale = (lo: number, hi: number): [number, number] => {
    const mid = (lo + hi) / 2;
    const half = ((hi - lo) / 2) * k;
    return [mid - half, mid + half];
  };
  return { x: scale(m.x.lo, m.x.hi), y: scale(m.y.lo, m.y.hi) };
}

const TOOL_TEXT: Record<PlotTool, { label: string; glyph: string }> = {
  save: { label: 'Save the plot as a PNG image', glyph: '⤓' },
  zoomIn: { label: 'Zoom in', glyph: '+' },
  zoomOut: { label: 'Zoom out', glyph: '−' },
  reset: { label: 'Reset the axes', glyph: '⟲' },
};

/** Save the drawn SVG as a PNG at twice its size, on the page's background. */
function savePng(svg: SVGSVGElement, bg: string, name: string) {
  const w = svg.width.baseVal.value;
  const h = svg.height.baseVal.value;
  const copy = svg.cloneNode(true) as SVGSVGElement;
  copy.setAttribute('xmlns', 'http://www.w3.org/2000/svg');
  copy.setAttribute('font-family', getComputedStyle(svg).fontFamily);
  copy.querySelector('.chart-readout')?.remove();
  const url = URL.createObjectURL(
    new Blob([new XMLSerializer().serializeToString(copy)], { type: 'image/svg+xml' }),
  );
  const img = new Image();
  img.onload = () => {
    const canvas = document.createElement('canvas');
    canvas.width = w * 2;
    canvas.height = h * 2;
    const ctx = canvas.getContext('2d');
    URL.revokeObjectURL(url);
    if (!ctx) return;
    ctx.fillStyle = bg;
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    ctx.scale(2, 2);
    ctx.drawImage(img, 0, 0, w, h);
    canvas.toBlob((b) => b && downloadFile(name, b, 'image/png'), 'image/png');
  };
  img.onerror = () => URL.revokeObjectURL(url);
  img.src = url;
}

/**
 * A plot drawn by the project's own chart (./chart): an SVG laid out from Plotly-shaped traces and
 * layout, drawn once the plot comes near the screen (the chart's code loads then, with the page's
 * first plot: a page whose plots stay folded never fetches it). A plot far off screen does not redraw on
 * every change (a storm of changes would redraw every plot of the page each time): it draws its
 * latest data when it comes back near the viewport. The pointer reads the nearest point out; a
 * mouse drag zooms to a box, a double click goes back; the tool buttons (shown on hover or focus)
 * zoom, reset and save a PNG.
 */
export function Plot({ data, layout, height = 280, ariaLabel, label, description, testId }: PlotProps) {
  const descId = `${useId()}-description`;
  const box = useRef<HTMLElement>(null);
  const svgRef = useRef<SVGSVGElement>(null);
  const seen = useSeenOnce(box);
  const width = useWidth(box, 0);
  const present = usePresent();
  const [near, setNear] = useState(true);
  const [chart, setChart] = useState<ChartModule | null>(null);
  const [loadFailed, setLoadFailed] = useState(false);
  useEffect(() => {
    if (!seen) return;
    let alive = true;
    loadChart().then(
      (m) => alive && setChart(m),
      () => alive && setLoadFailed(true),
    );
    return () => {
      alive = false;
    };
  }, [seen]);
  useEffect(() => {
    const node = box.current;
    return node ? observeVisibility(node, setNear, NEAR_VIEW) : undefined;
  }, []);
  const themeKey =
    typeof document !== 'undefined' ? `${document.documentElement.dataset.theme}-${present}` : '';

  // Layouts are small: compare them by content, so an inline `layout={{…}}` does not redraw on
  // every render of the parent. Data is compared by identity (memoise it).
  const sameLayout = useSameByContent(layout);
  const clean = useMemo(() => sanitizeTraces(data), [data]);
  /** The data drawn: the latest while near the screen, else the last drawn. */
  const shown = useRef(clean);
  if (near) shown.current = clean;
  const drawn = shown.current;

  const [view, setView] = useState<View>({});
  // a new layout starts from its own axes (no zoom carried over)
  useEffect(() => setView((v) => (v.x || v.y ? {} : v)), [sameLayout]);
  const [readout, setReadout] = useState<Readout | null>(null);
  const [drag, setDrag] = useState<{ x0: number; y0: number; box: Rect } | null>(null);

  // sizes and colours follow the theme and classroom mode (themeKey); read once per theme, not per
  // change of the data (a storm of changes would read the page's computed style on every one)
  const style = useMemo(() => {
    if (typeof document === 'undefined') return null;
    const cs = getComputedStyle(document.documentElement);
    const font = Number(cs.getPropertyValue('--plot-font-size').trim()) || 13;
    const own = sameLayout?.xaxis?.tickfont?.size ?? 0;
    const tick = Math.max(font, own, present ? PRESENT_TICK_PX : 0);
    // the 2s and 5s between a log axis's decades are smaller, except in a lecture hall
    const minorTick = present ? tick : Math.round(tick * 0.8);
    const tools = touchOnly() ? 0 : PLOT_TOOLS.length * TOOL_WIDTH + 8;
    const family = getComputedStyle(document.body).fontFamily;
    return {
      font,
      tick,
      minorTick,
      measure: measurer(family),
      topRight: tools,
      colors: themeColors(),
      themeKey,
    };
  }, [themeKey, present, sameLayout]);

  const result = useMemo(() => {
    if (loadFailed) return 'failed' as const;
    if (!chart || !style || width <= 0) return null;
    try {
      return chart.layoutChart(drawn.data, sameLayout ?? {}, width, height, style, view);
    } catch {
      return 'failed' as const;
    }
  }, [chart, loadFailed, style, width, height, drawn, view, sameLayout]);
  const model = result === 'failed' ? null : result;
  useEffect(() => setReadout(null), [model]);
  // a readout over the plot is dismissed by Escape without moving the pointer (WCAG 1.4.13)
  const showing = readout !== null;
  useEffect(() => {
    if (!showing) return;
    const onKey = (e: KeyboardEvent) => e.key === 'Escape' && setReadout(null);
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [showing]);

  const local = (e: ReactPointerEvent) => {
    const r = (e.currentTarget as Element).getBoundingClientRect();
    return { x: e.clientX - r.left, y: e.clientY - r.top };
  };
  const inPlot = (p: { x: number; y: number }) =>
    !!model &&
    p.x >= model.plot.x &&
    p.x <= model.plot.x + model.plot.w &&
    p.y >= model.plot.y &&
    p.y <= model.plot.y + model.plot.h;
  const onPointerDown = (e: ReactPointerEvent) => {
    const p = local(e);
    if (!model) return;
    if (e.pointerType !== 'mouse') {
      setReadout(chart!.readoutAt(model, p.x, p.y, 32));
      return;
    }
    if (e.button !== 0 || !inPlot(p)) return;
    (e.currentTarget as Element).setPointerCapture?.(e.pointerId);
    setDrag({ x0: p.x, y0: p.y, box: { x: p.x, y: p.y, w: 0, h: 0 } });
  };
  const onPointerMove = (e: ReactPointerEvent) => {
    if (!model || e.pointerType !== 'mouse') return;
    const p = local(e);
    if (drag) {
      const { plot } = model;
      const x = Math.min(Math.max(p.x, plot.x), plot.x + plot.w);
      const y = Math.min(Math.max(p.y, plot.y), plot.y + plot.h);
      setDrag({
        ...drag,
        box: {
          x: Math.min(drag.x0, x),
          y: Math.min(drag.y0, y),
          w: Math.abs(x - drag.x0),
          h: Math.abs(y - drag.y0),
        },
      });
      return;
    }
    const next = chart!.readoutAt(model, p.x, p.y);
    // the same point again: no new state, nothing drawn
    setReadout((old) => (old && next && old.x === next.x && old.y === next.y ? old : next));
  };
  const onPointerUp = () => {
    if (!drag || !model) return;
    const { box: b } = drag;
    setDrag(null);
    const wide = b.w >= 8;
    const tall = b.h >= 8;
    if (!wide && !tall) return;
    const range = (a: typeof model.x, p0: number, p1: number): [number, number] => {
      const u0 = chart!.pxToUnits(a, p0);
      const u1 = chart!.pxToUnits(a, p1);
      return [Math.min(u0, u1), Math.max(u0, u1)];
    };
    setView({
      x: wide ? range(model.x, b.x, b.x + b.w) : [model.x.lo, model.x.hi],
      y: tall ? range(model.y, b.y, b.y + b.h) : [model.y.lo, model.y.hi],
    });
  };
  const press = (b: PlotTool) => {
    if (!model) return;
    if (b === 'zoomIn') setView(zoomed(model, 0.5));
    else if (b === 'zoomOut') setView(zoomed(model, 2));
    else if (b === 'reset') setView({});
    else if (svgRef.current && style)
      savePng(
        svgRef.current,
        style.colors.bg,
        `${(label ?? ariaLabel ?? 'plot').replace(/[^\w-]+/g, '-').slice(0, 60)}.png`,
      );
  };

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
      {result === 'failed' ? <p className="plot-placeholder">The plot could not be drawn.</p> : null}
      {!result ? <p className="plot-placeholder">Loading plot…</p> : null}
      {model && chart ? (
        <div
          className="plot-canvas"
          onPointerDown={onPointerDown}
          onPointerMove={onPointerMove}
          onPointerUp={onPointerUp}
          onPointerCancel={() => setDrag(null)}
          onPointerLeave={() => !drag && setReadout(null)}
          onDoubleClick={() => setView({})}
        >
          <chart.ChartSvg
            model={model}
            colors={style!.colors}
            tick={style!.tick}
            minorTick={style!.minorTick}
            font={style!.font}
            readout={readout}
            zoomBox={drag && (drag.box.w > 2 || drag.box.h > 2) ? drag.box : null}
            svgRef={svgRef}
          />
        </div>
      ) : null}
      {model && !touchOnly() ? (
        <div className="plot-tools">
          {PLOT_TOOLS.map((b) => (
            <button
              key={b}
              type="button"
              className="plot-tool"
              aria-label={TOOL_TEXT[b].label}
              title={TOOL_TEXT[b].label}
              onClick={() => press(b)}
            >
              {TOOL_TEXT[b].glyph}
            </button>
          ))}
        </div>
      ) : null}
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
