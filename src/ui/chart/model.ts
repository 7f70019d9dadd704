/**
 * A chart laid out: from traces and a layout (./types) and the figure's size, everything the SVG
 * draws, in pixels: the plot area and margins that fit the tick labels, titles, legend and colour
 * bar; the axes and their ticks; every trace's marks as SVG path data; and what the pointer's
 * readout can find. Pure (text is measured through the given function), so tests read a chart's
 * marks against its data without a browser.
 */
import { colorCss, DIVERGING, normalizeValue, VIRIDIS } from '../../core/colormap';
import { formatNumber } from '../../core/format';
import { niceTicks, tickLabel } from '../axis';
import { coordText } from '../chartScale';
import { autoRange, makeTicks, toUnits, unitsToPx, type Axis, type AxisKind, type Tick } from './axes';
import type {
  AxisSpec,
  ChartLayout,
  ChartTrace,
  Data,
  HeatmapTrace,
  LegendSpec,
  LineStyle,
  MarkerSymbol,
  ScatterTrace,
} from './types';

export interface ChartStyle {
  /** Font size (px) of titles and the legend. */
  font: number;
  /** Font size (px) of tick labels. */
  tick: number;
  /** Font size (px) of the 2s and 5s between a log axis's decades; 0.8 × `tick` when absent. */
  minorTick?: number;
  /** Width (px) of `text` set at `size` px. */
  measure: (text: string, size: number) => number;
}

/** A zoomed view: the axes' ranges in axis units (log10 on a log axis), instead of their own. */
export interface View {
  x?: readonly [number, number];
  y?: readonly [number, number];
}

export interface Rect {
  x: number;
  y: number;
  w: number;
  h: number;
}

export interface Stroke {
  color: string;
  width: number;
  /** An SVG stroke-dasharray, or undefined for a solid line. */
  dash?: string;
}

export type Mark =
  | ({ kind: 'line'; d: string; opacity: number } & Stroke)
  | { kind: 'area'; d: string; color: string; opacity: number }
  | { kind: 'markers'; d: string; fill: string; stroke?: Stroke; opacity: number }
  | { kind: 'cells'; cells: { x: number; y: number; w: number; h: number; color: string }[] };

export interface Swatch {
  line?: Stroke;
  marker?: { symbol: MarkerSymbol; color: string; size: number; stroke?: Stroke };
  box?: { color: string; opacity: number };
}

export interface LegendItem {
  text: string;
  /** Left end of the swatch and the row's middle (px). */
  x: number;
  y: number;
  swatch: Swatch;
}

/** What the pointer's readout finds: a trace's points, or its boxes (bars, bins, cells). */
export type Target =
  | {
      kind: 'points';
      name: string;
      color: string;
      px: number[];
      py: number[];
      x: number[];
      y: number[];
      /** A line of text per point, or none. */
      text: (string | undefined)[];
    }
  | { kind: 'boxes'; name: string; color: string; boxes: { r: Rect; text: string }[] };

export interface ChartModel {
  width: number;
  height: number;
  plot: Rect;
  x: Axis;
  y: Axis;
  xTitle: string;
  yTitle: string;
  /** The title's centre baseline, or null. */
  title: { text: string; x: number; y: number } | null;
  marks: Mark[];
  shapes: ({ d: string } & Stroke)[];
  legend: { items: LegendItem[]; rowHeight: number; box: Rect | null };
  colorbar: { r: Rect; stops: { t: number; color: string }[]; ticks: Tick[] } | null;
  targets: Target[];
}

/** Tick labels are at most every this many px along x, and along y. */
const X_SPACING = 80;
const Y_SPACING = 42;
/** Swatch length and the gaps of a legend entry (px). */
const SWATCH = 30;
const ITEM_GAP = 16;
const COLORBAR = 14;

/** The gray of Plotly-shaped traces that give no colour, in place of Plotly's default cycle. */
const SERIES_DEFAULT = ['var(--series-1)', 'var(--series-2)', 'var(--series-3)', 'var(--series-4)'];

/** The names of Plotly's dashes as dash lengths in multiples of the line width (at least 3 px). */
const DASH_UNITS: Record<string, number[]> = {
  dot: [1, 1],
  dash: [3, 3],
  longdash: [5, 5],
  dashdot: [3, 1, 1, 1],
  longdashdot: [5, 2, 1, 2],
};

/**
 * An SVG dash array for a Plotly dash name or px list at this line width: dashes scale with the
 * width, as plotly.js draws them (src/components/drawing, dashStyle), so a thin dotted line stays dotted.
 */
export function dashArray(dash: string | undefined, width: number): string | undefined {
  if (!dash || dash === 'solid') return undefined;
  const units = DASH_UNITS[dash];
  if (units) {
    const w = Math.max(width, 3);
    return units.map((k) => k * w).join(' ');
  }
  const px = dash.split(',').map((s) => parseFloat(s));
  return px.every((v) => Number.isFinite(v) && v >= 0) ? px.join(' ') : undefined;
}

/** Plain text of a name that may carry <sub>/<sup> (for measuring and for the readout). */
export function plainText(s: string): string {
  return s.replace(/<\/?(sub|sup)>/g, '');
}

const num = (v: Data[number] | undefined): number => (typeof v === 'number' ? v : NaN);

function strokeOf(line: LineStyle | undefined, fallback: string): Stroke {
  const width = line?.width ?? 2;
  const color = line?.color ?? fallback;
  const dash = dashArray(line?.dash, width);
  return dash ? { color, width, dash } : { color, width };
}

/** A scatter trace's mode: Plotly's default is lines and markers below 20 points, lines above. */
function modeOf(t: ScatterTrace): { lines: boolean; markers: boolean } {
  const mode = t.mode ?? (t.x.length < 20 ? 'lines+markers' : 'lines');
  return { lines: mode.includes('lines'), markers: mode.includes('markers') };
}

/** Histogram counts of `x` in the trace's bins: [start, start + size), …, the last bin closed at its end. */
export function histogramCounts(x: Data, bins: { start: number; end: number; size: number }): number[] {
  const { start, size } = bins;
  if (!(size > 0) || !(bins.end > start) || !Number.isFinite(bins.end - start)) return [];
  const nb = Math.max(1, Math.min(100_000, Math.ceil((bins.end - start) / size - 1e-9)));
  const counts = new Array<number>(nb).fill(0);
  const end = start + nb * size;
  for (let i = 0; i < x.length; i++) {
    const v = num(x[i]);
    if (!(v >= start && v <= end)) continue;
    counts[Math.min(nb - 1, Math.floor((v - start) / size))]++;
  }
  return counts;
}

/** Bars of a bar or histogram trace: [left, right, height] in data units. */
function barsOf(t: ChartTrace, bargap: number): [number, number, number][] {
  if (t.type === 'histogram') {
    const counts = histogramCounts(t.x, t.xbins);
    const { start, size } = t.xbins;
    const g = (size * bargap) / 2;
    return counts.map((c, k) => [start + k * size + g, start + (k + 1) * size - g, c]);
  }
  if (t.type !== 'bar') return [];
  const xs: number[] = [];
  for (let i = 0; i < t.x.length; i++) xs.push(num(t.x[i]));
  let w = t.width;
  if (w === undefined) {
    const sorted = xs.filter(Number.isFinite).sort((a, b) => a - b);
    let gap = Infinity;
    for (let k = 1; k < sorted.length; k++)
      if (sorted[k] > sorted[k - 1]) gap = Math.min(gap, sorted[k] - sorted[k - 1]);
    w = (Number.isFinite(gap) ? gap : 1) * (1 - bargap);
  }
  return xs.map((x, i) => [x - w / 2, x + w / 2, num(t.y[i])]);
}

/** The extents (axis units) of every trace's data and of data-anchored shapes, per axis. */
function extents(
  traces: readonly ChartTrace[],
  layout: ChartLayout,
  kx: AxisKind,
  ky: AxisKind,
  bargap: number,
) {
  let x: [number, number] | null = null;
  let y: [number, number] | null = null;
  const addX = (v: number) => {
    const u = toUnits(kx, v);
    if (Number.isFinite(u)) x = x ? [Math.min(x[0], u), Math.max(x[1], u)] : [u, u];
  };
  const addY = (v: number) => {
    const u = toUnits(ky, v);
    if (Number.isFinite(u)) y = y ? [Math.min(y[0], u), Math.max(y[1], u)] : [u, u];
  };
  let markers = false;
  let bars = false;
  for (const t of traces) {
    if (t.type === 'heatmap') {
      const [x0, x1] = cellEdges(t.x);
      const [y0, y1] = cellEdges(t.y);
      addX(x0);
      addX(x1);
      addY(y0);
      addY(y1);
    } else if (t.type === 'bar' || t.type === 'histogram') {
      bars = true;
      for (const [l, r, h] of barsOf(t, bargap)) {
        if (!Number.isFinite(h)) continue;
        addX(l);
        addX(r);
        addY(h);
        addY(0);
      }
    } else {
      const { markers: m } = modeOf(t);
      markers ||= m;
      const n = Math.min(t.x.length, t.y.length);
      for (let i = 0; i < n; i++) {
        const a = num(t.x[i]);
        const b = num(t.y[i]);
        if (Number.isFinite(toUnits(kx, a)) && Number.isFinite(toUnits(ky, b))) {
          addX(a);
          addY(b);
        }
      }
    }
  }
  for (const s of layout.shapes ?? []) {
    if (s.xref !== 'paper') [s.x0, s.x1].forEach(addX);
    if (s.yref !== 'paper') [s.y0, s.y1].forEach(addY);
  }
  return { x: x as [number, number] | null, y: y as [number, number] | null, markers, bars };
}

/** The outer edges of evenly spaced cell centres. */
function cellEdges(c: readonly number[]): [number, number] {
  if (c.length === 0) return [NaN, NaN];
  const d = c.length > 1 ? (c[c.length - 1] - c[0]) / (c.length - 1) : 1;
  return [c[0] - d / 2, c[c.length - 1] + d / 2];
}

/** The legend's entries: named traces that show in it, one per legend group. */
function legendEntries(
  traces: readonly ChartTrace[],
  layout: ChartLayout,
): { text: string; swatch: Swatch }[] {
  const shown = traces.filter((t) => t.type !== 'heatmap' && t.showlegend !== false && t.name);
  if (layout.showlegend === false || (layout.showlegend !== true && shown.length < 2)) return [];
  const groups = new Set<string>();
  const out: { text: string; swatch: Swatch }[] = [];
  traces.forEach((t, i) => {
    if (!shown.includes(t)) return;
    if (t.legendgroup) {
      if (groups.has(t.legendgroup)) return;
      groups.add(t.legendgroup);
    }
    out.push({ text: t.name!, swatch: swatchOf(t, i) });
  });
  return out;
}

function colorOf(t: ChartTrace, i: number): string {
  const fallback = SERIES_DEFAULT[i % SERIES_DEFAULT.length];
  if (t.type === 'scatter' || t.type === undefined) {
    const mc = t.marker?.color;
    return t.line?.color ?? (typeof mc === 'string' ? mc : fallback);
  }
  if (t.type === 'heatmap') return fallback;
  const c = t.marker?.color;
  return typeof c === 'string' ? c : fallback;
}

function swatchOf(t: ChartTrace, i: number): Swatch {
  const color = colorOf(t, i);
  if (t.type === 'bar' || t.type === 'histogram')
    return { box: { color, opacity: (t.opacity ?? 1) * (t.marker?.opacity ?? 1) } };
  if (t.type === 'heatmap') return {};
  const { lines, markers } = modeOf(t);
  const sw: Swatch = {};
  if (lines && (t.line?.width ?? 2) > 0) sw.line = strokeOf(t.line, color);
  if (markers) sw.marker = markerStyle(t, color, 0);
  return sw;
}

function markerStyle(t: ScatterTrace, color: string, i: number) {
  const m = t.marker ?? {};
  const size = typeof m.size === 'number' ? m.size : Array.isArray(m.size) ? (m.size[i] ?? 6) : 6;
  const c = typeof m.color === 'string' ? m.color : Array.isArray(m.color) ? (m.color[i] ?? color) : color;
  const symbol = m.symbol ?? 'circle';
  const lw = m.line?.width ?? (symbol === 'circle-open' ? 2 : 0);
  const stroke = lw > 0 ? { color: m.line?.color ?? c, width: lw } : undefined;
  return stroke ? { symbol, color: c, size, stroke } : { symbol, color: c, size };
}

/** SVG path data of one marker of `symbol` and diameter `size` centred at (x, y). */
export function markerPath(symbol: MarkerSymbol, x: number, y: number, size: number): string {
  const r = size / 2;
  const f = (v: number) => coordText(v, 1);
  switch (symbol) {
    case 'square':
      return `M${f(x - r)} ${f(y - r)}h${f(2 * r)}v${f(2 * r)}h${f(-2 * r)}Z`;
    case 'diamond': {
      const d = r * 1.3;
      return `M${f(x)} ${f(y - d)}L${f(x + d)} ${f(y)}L${f(x)} ${f(y + d)}L${f(x - d)} ${f(y)}Z`;
    }
    case 'x': {
      // a filled cross: two bars of width r/2 crossing at the centre
      const a = r / Math.SQRT2;
      const w = r / 3;
      return (
        `M${f(x - a - w)} ${f(y - a + w)}L${f(x - a + w)} ${f(y - a - w)}L${f(x + a + w)} ${f(y + a - w)}L${f(x + a - w)} ${f(y + a + w)}Z` +
        `M${f(x + a - w)} ${f(y - a - w)}L${f(x + a + w)} ${f(y - a + w)}L${f(x - a + w)} ${f(y + a + w)}L${f(x - a - w)} ${f(y + a - w)}Z`
      );
    }
    default:
      return `M${f(x - r)} ${f(y)}a${f(r)} ${f(r)} 0 1 0 ${f(2 * r)} 0a${f(r)} ${f(r)} 0 1 0 ${f(-2 * r)} 0Z`;
  }
}

/** Lay the legend's entries out in rows of at most `width` px (one per row when vertical); offsets from the rows' start. */
function flowLegend(
  entries: { text: string; swatch: Swatch }[],
  width: number,
  vertical: boolean,
  style: ChartStyle,
): { rows: { text: string; swatch: Swatch; dx: number }[][]; widest: number } {
  const rows: { text: string; swatch: Swatch; dx: number }[][] = [];
  let dx = 0;
  let widest = 0;
  for (const e of entries) {
    const w = SWATCH + 6 + style.measure(plainText(e.text), style.font);
    if (!rows.length || vertical || (dx > 0 && dx + w > width)) {
      rows.push([]);
      dx = 0;
    }
    rows[rows.length - 1].push({ ...e, dx });
    dx += w + ITEM_GAP;
    widest = Math.max(widest, dx - ITEM_GAP);
  }
  return { rows, widest };
}

function axisKind(a: AxisSpec | undefined): AxisKind {
  return a?.type === 'log' ? 'log' : 'linear';
}

/** Where the legend goes: above the plot (Plotly's y > 1), below it (y < 0), or inside it. */
function legendPlace(l: LegendSpec | undefined): 'above' | 'below' | 'inside' {
  const y = l?.y ?? 1.02;
  return y > 1 ? 'above' : y < 0 ? 'below' : 'inside';
}

/**
 * Lay out the chart at `width` × `height` px. Margins start at the layout's and grow to fit what
 * sits around the plot area, so the figure keeps its height and the plot area takes the rest.
 */
export function layoutChart(
  traces: readonly ChartTrace[],
  layout: ChartLayout,
  width: number,
  height: number,
  style: ChartStyle,
  view: View = {},
): ChartModel {
  const m = { l: 56, r: 16, t: 12, b: 44, ...layout.margin };
  const kx = axisKind(layout.xaxis);
  const ky = axisKind(layout.yaxis);
  const bargap = layout.bargap ?? (traces.some((t) => t.type === 'bar') ? 0.2 : 0);
  const ext = extents(traces, layout, kx, ky, bargap);
  const xr = view.x ?? layout.xaxis?.range ?? autoRange(ext.x, kx, ext.markers ? 0.03 : 0);
  const yr = view.y ?? layout.yaxis?.range ?? autoRange(ext.y, ky, ext.bars ? 0.08 : 0.06, ext.bars);
  const xTitle = layout.xaxis?.title?.text ?? '';
  const yTitle = layout.yaxis?.title?.text ?? '';
  const lineH = (size: number) => Math.ceil(size * 1.3);

  // the colour bar (a heatmap's scale) on the right
  const heat = traces.find((t): t is HeatmapTrace => t.type === 'heatmap' && t.showscale === true);
  const barTicks = heat ? niceTicks(heat.zmin, heat.zmax, 4) : null;
  const barLabels = barTicks ? barTicks.ticks.map((v) => tickLabel(v, barTicks.step)) : [];
  const barWidth = heat
    ? 10 + COLORBAR + 4 + Math.max(0, ...barLabels.map((s) => style.measure(s, style.tick)))
    : 0;

  // the legend's rows (laid out against the whole width first; refined once the left margin is known)
  const entries = legendEntries(traces, layout);
  const place = legendPlace(layout.legend);
  const vertical = layout.legend?.orientation === 'v';
  const rowH = Math.max(lineH(style.font), 18);
  const titleH = layout.title?.text ? lineH(style.font * 1.1) + 6 : 0;
  const tickH = lineH(style.tick);

  let left = m.l;
  let legend = flowLegend(entries, width - left - m.r, vertical, style);
  let top = 0;
  let bottom = 0;
  let plot: Rect = { x: 0, y: 0, w: 0, h: 0 };
  let x: Axis = { kind: kx, lo: 0, hi: 1, px0: 0, px1: 1, ticks: [] };
  let y: Axis = { kind: ky, lo: 0, hi: 1, px0: 1, px1: 0, ticks: [] };
  for (let pass = 0; pass < 2; pass++) {
    const legendH = entries.length && place !== 'inside' ? legend.rows.length * rowH + 4 : 0;
    top = Math.max(m.t, titleH + (place === 'above' ? legendH : 0) + Math.ceil(style.tick / 2) + 4);
    bottom =
      Math.max(m.b, tickH + 6 + (xTitle ? lineH(style.font) + 4 : 0) + 2) +
      (place === 'below' ? legendH + 4 : 0);
    const ph = Math.max(20, height - top - bottom);
    const yBase = {
      kind: ky,
      lo: Math.min(yr[0], yr[1]),
      hi: Math.max(yr[0], yr[1]),
      px0: top + ph,
      px1: top,
    };
    if (layout.yaxis?.autorange === 'reversed') [yBase.px0, yBase.px1] = [yBase.px1, yBase.px0];
    y = { ...yBase, ticks: makeTicks(yBase, Y_SPACING, () => style.tick * 1.2) };
    const yLabelW = Math.max(
      0,
      ...y.ticks.map((t) =>
        style.measure(t.label, t.minor ? (style.minorTick ?? style.tick * 0.8) : style.tick),
      ),
    );
    left = Math.max(m.l, Math.ceil(yLabelW + 8 + (yTitle ? lineH(style.font) + 6 : 0) + 2));
    // the last x label may reach past the plot's right end by half its width
    let right = m.r + barWidth;
    let pw = Math.max(20, width - left - right);
    const xBase = {
      kind: kx,
      lo: Math.min(xr[0], xr[1]),
      hi: Math.max(xr[0], xr[1]),
      px0: left,
      px1: left + pw,
    };
    if (layout.xaxis?.autorange === 'reversed') [xBase.px0, xBase.px1] = [xBase.px1, xBase.px0];
    const xm = (s: string) => style.measure(s, style.tick);
    let xt = makeTicks(xBase, X_SPACING, xm);
    const overhang = Math.max(0, ...xt.map((t) => t.px + xm(t.label) / 2 - (left + pw)));
    if (overhang > right - barWidth) {
      right = barWidth + Math.ceil(overhang) + 2;
      pw = Math.max(20, width - left - right);
      xBase.px1 = layout.xaxis?.autorange === 'reversed' ? left : left + pw;
      xBase.px0 = layout.xaxis?.autorange === 'reversed' ? left + pw : left;
      xt = makeTicks(xBase, X_SPACING, xm);
    }
    x = { ...xBase, ticks: xt };
    plot = { x: left, y: top, w: pw, h: ph };
    legend = flowLegend(entries, place === 'inside' ? pw * 0.9 : width - left - 8, vertical, style);
  }

  // the legend's entries placed
  const items: LegendItem[] = [];
  let box: Rect | null = null;
  if (entries.length) {
    const h = legend.rows.length * rowH;
    const w = legend.widest;
    const spec = layout.legend ?? {};
    let bx = plot.x;
    let by: number;
    if (place === 'above') by = titleH + 2;
    else if (place === 'below') by = plot.y + plot.h + bottom - (legend.rows.length * rowH + 4);
    else {
      const fx = spec.x ?? 0.02;
      const fy = spec.y ?? 0.98;
      bx = plot.x + fx * plot.w - (spec.xanchor === 'right' ? w + 8 : 0) + (spec.xanchor === 'right' ? 0 : 4);
      by = plot.y + (1 - fy) * plot.h + (spec.yanchor === 'bottom' ? -h - 4 : 4);
    }
    box = { x: bx - 4, y: by, w: w + 8, h };
    legend.rows.forEach((row, r) =>
      row.forEach((e) =>
        items.push({ text: e.text, swatch: e.swatch, x: bx + e.dx, y: by + r * rowH + rowH / 2 }),
      ),
    );
  }

  const model: ChartModel = {
    width,
    height,
    plot,
    x,
    y,
    xTitle,
    yTitle,
    title: layout.title?.text
      ? { text: layout.title.text, x: plot.x + plot.w / 2, y: lineH(style.font * 1.1) }
      : null,
    marks: [],
    shapes: [],
    legend: { items, rowHeight: rowH, box: place === 'inside' ? box : null },
    colorbar: null,
    targets: [],
  };
  drawTraces(model, traces, bargap);
  for (const s of layout.shapes ?? []) {
    const px = (v: number) => (s.xref === 'paper' ? plot.x + v * plot.w : unitsToPx(x, toUnits(kx, v)));
    const py = (v: number) => (s.yref === 'paper' ? plot.y + (1 - v) * plot.h : unitsToPx(y, toUnits(ky, v)));
    const pts = [px(s.x0), py(s.y0), px(s.x1), py(s.y1)];
    if (!pts.every(Number.isFinite)) continue;
    const f = (v: number) => coordText(v, 1);
    model.shapes.push({
      d: `M${f(pts[0])} ${f(pts[1])}L${f(pts[2])} ${f(pts[3])}`,
      ...strokeOf(s.line, 'var(--fg)'),
    });
  }
  if (heat && barTicks) {
    const r = { x: plot.x + plot.w + 10, y: plot.y, w: COLORBAR, h: plot.h };
    const map = heat.colorscale === 'RdBu' ? DIVERGING : VIRIDIS;
    const stops = Array.from({ length: 11 }, (_, k) => ({ t: k / 10, color: colorCss(k / 10, map) }));
    const ticks = barTicks.ticks
      .filter((v) => v >= heat.zmin && v <= heat.zmax)
      .map((v) => ({
        px: r.y + r.h * (1 - normalizeValue(v, heat.zmin, heat.zmax)),
        label: tickLabel(v, barTicks.step),
      }));
    model.colorbar = { r, stops, ticks };
  }
  return model;
}

/** Every trace's marks and readout targets, in drawing order. */
function drawTraces(model: ChartModel, traces: readonly ChartTrace[], bargap: number): void {
  const { x, y } = model;
  const f = (v: number) => coordText(v, 1);
  const name = (t: ChartTrace) => plainText(t.name ?? '');
  const fmt = (v: number) => formatNumber(v, 4);
  const xName = plainText(model.xTitle) || 'x';
  const yName = plainText(model.yTitle) || 'y';
  const pxOf = (v: number) => unitsToPx(x, toUnits(x.kind, v));
  const pyOf = (v: number) => unitsToPx(y, toUnits(y.kind, v));
  let prevLine: [number, number][] = [];

  traces.forEach((t, i) => {
    const color = colorOf(t, i);
    const opacity = t.opacity ?? 1;
    if (t.type === 'heatmap') {
      const map = t.colorscale === 'RdBu' ? DIVERGING : VIRIDIS;
      const cells: { x: number; y: number; w: number; h: number; color: string }[] = [];
      const boxes: { r: Rect; text: string }[] = [];
      const dx = t.x.length > 1 ? (t.x[t.x.length - 1] - t.x[0]) / (t.x.length - 1) : 1;
      const dy = t.y.length > 1 ? (t.y[t.y.length - 1] - t.y[0]) / (t.y.length - 1) : 1;
      t.z.forEach((row, r) =>
        row.forEach((z, c) => {
          if (!Number.isFinite(z) || c >= t.x.length || r >= t.y.length) return;
          const xa = pxOf(t.x[c] - dx / 2);
          const xb = pxOf(t.x[c] + dx / 2);
          const ya = pyOf(t.y[r] - dy / 2);
          const yb = pyOf(t.y[r] + dy / 2);
          const rect = {
            x: Math.min(xa, xb),
            y: Math.min(ya, yb),
            w: Math.abs(xb - xa),
            h: Math.abs(yb - ya),
          };
          // a hairline of overlap hides the seams antialiasing leaves between cells
          cells.push({
            ...rect,
            w: rect.w + 0.5,
            h: rect.h + 0.5,
            color: colorCss(normalizeValue(z, t.zmin, t.zmax), map),
          });
          boxes.push({ r: rect, text: `${xName} ${fmt(t.x[c])}, ${yName} ${fmt(t.y[r])}: ${fmt(z)}` });
        }),
      );
      model.marks.push({ kind: 'cells', cells });
      model.targets.push({ kind: 'boxes', name: name(t), color, boxes });
      return;
    }
    if (t.type === 'bar' || t.type === 'histogram') {
      const y0 = pyOf(y.kind === 'log' ? 10 ** y.lo : 0);
      let d = '';
      const boxes: { r: Rect; text: string }[] = [];
      for (const [l, r, h] of barsOf(t, bargap)) {
        if (!Number.isFinite(h) || h === 0) continue;
        const xa = pxOf(l);
        const xb = pxOf(r);
        const yh = pyOf(h);
        if (![xa, xb, yh].every(Number.isFinite)) continue;
        d += `M${f(xa)} ${f(y0)}H${f(xb)}V${f(yh)}H${f(xa)}Z`;
        const rect = { x: Math.min(xa, xb), y: Math.min(y0, yh), w: Math.abs(xb - xa), h: Math.abs(yh - y0) };
        boxes.push({
          r: rect,
          text:
            t.type === 'histogram'
              ? `${fmt(h)} in [${fmt(l)}, ${fmt(r)})`
              : `${xName} ${fmt((l + r) / 2)}, ${yName} ${fmt(h)}`,
        });
      }
      model.marks.push({ kind: 'area', d, color, opacity: opacity * (t.marker?.opacity ?? 1) });
      model.targets.push({ kind: 'boxes', name: name(t), color, boxes });
      return;
    }
    // scatter
    const n = Math.min(t.x.length, t.y.length);
    const pts: [number, number][] = [];
    const tx: number[] = [];
    const ty: number[] = [];
    const tt: (string | undefined)[] = [];
    let d = '';
    let pen = false;
    for (let k = 0; k < n; k++) {
      const a = num(t.x[k]);
      const b = num(t.y[k]);
      const px = pxOf(a);
      const py = pyOf(b);
      if (!Number.isFinite(px) || !Number.isFinite(py)) {
        pen = false;
        continue;
      }
      d += `${pen ? 'L' : 'M'}${f(px)} ${f(py)}`;
      pen = true;
      pts.push([px, py]);
      tx.push(a);
      ty.push(b);
      tt.push(t.text?.[k]);
    }
    const { lines, markers } = modeOf(t);
    if (t.fill === 'tonexty' && prevLine.length && pts.length) {
      const back = [...prevLine].reverse();
      const ring = [...pts, ...back].map(([a, b], k) => `${k ? 'L' : 'M'}${f(a)} ${f(b)}`).join('');
      model.marks.push({ kind: 'area', d: `${ring}Z`, color: t.fillcolor ?? color, opacity });
    }
    const stroke = strokeOf(t.line, color);
    if (lines && stroke.width > 0 && d) model.marks.push({ kind: 'line', d, opacity, ...stroke });
    if (markers) {
      // one path per marker colour
      const byColor = new Map<string, { d: string; stroke?: Stroke; open: boolean }>();
      for (let k = 0; k < n; k++) {
        const px = pxOf(num(t.x[k]));
        const py = pyOf(num(t.y[k]));
        if (!Number.isFinite(px) || !Number.isFinite(py)) continue;
        const ms = markerStyle(t, color, k);
        if (!(ms.size > 0)) continue;
        const key = ms.color;
        const g = byColor.get(key) ?? { d: '', stroke: ms.stroke, open: ms.symbol === 'circle-open' };
        g.d += markerPath(ms.symbol, px, py, ms.size);
        byColor.set(key, g);
      }
      for (const [c, g] of byColor)
        model.marks.push({
          kind: 'markers',
          d: g.d,
          fill: g.open ? 'none' : c,
          ...(g.stroke ? { stroke: g.open ? { ...g.stroke, color: c } : g.stroke } : {}),
          opacity: opacity * (t.marker?.opacity ?? 1),
        });
    }
    prevLine = pts;
    if (t.hoverinfo !== 'skip' && pts.length)
      model.targets.push({
        kind: 'points',
        name: name(t),
        color,
        px: pts.map((p) => p[0]),
        py: pts.map((p) => p[1]),
        x: tx,
        y: ty,
        text: tt,
      });
  });
}

/** The readout at pixel (px, py): the nearest point within `reach` px, else the box under it. */
export function readoutAt(
  model: ChartModel,
  px: number,
  py: number,
  reach = 24,
): { x: number; y: number; color: string; lines: string[] } | null {
  const { plot } = model;
  if (px < plot.x || px > plot.x + plot.w || py < plot.y || py > plot.y + plot.h) return null;
  const fmt = (v: number) => formatNumber(v, 4);
  let best: { d: number; x: number; y: number; color: string; lines: string[] } | null = null;
  for (const t of model.targets) {
    if (t.kind !== 'points') continue;
    for (let k = 0; k < t.px.length; k++) {
      const d = Math.hypot(t.px[k] - px, t.py[k] - py);
      if (d <= reach && (!best || d < best.d))
        best = {
          d,
          x: t.px[k],
          y: t.py[k],
          color: t.color,
          lines: [
            ...(t.name ? [t.name] : []),
            `${plainText(model.xTitle) || 'x'} ${fmt(t.x[k])}, ${plainText(model.yTitle) || 'y'} ${fmt(t.y[k])}`,
            ...(t.text[k] ? [plainText(t.text[k] ?? '')] : []),
          ],
        };
    }
  }
  if (best) return best;
  for (let i = model.targets.length - 1; i >= 0; i--) {
    const t = model.targets[i];
    if (t.kind !== 'boxes') continue;
    for (const b of t.boxes)
      if (px >= b.r.x && px <= b.r.x + b.r.w && py >= b.r.y && py <= b.r.y + b.r.h)
        return { x: px, y: py, color: t.color, lines: [...(t.name ? [t.name] : []), b.text] };
  }
  return null;
}
