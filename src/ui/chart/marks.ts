/**
 * The marks of a chart's traces: each trace drawn as SVG path data in the laid-out axes (lines,
 * fills, markers, bars, histogram bins, heatmap cells), its legend swatch, and what the pointer's
 * readout can find on it. Pure, like ./model, which lays the chart out and calls drawTraces.
 */
import { colorCss, DIVERGING, normalizeValue, VIRIDIS, type Colormap } from '../../core/colormap';
import { formatNumber } from '../../core/format';
import { coordText } from '../chartScale';
// traces that give no colour take the shared series palette's, in trace order
import { SERIES } from '../palette';
import { toUnits, unitsToPx } from './axes';
import type { Axis } from './axes';
import type {
  BarTrace,
  ChartTrace,
  Data,
  HeatmapTrace,
  HistogramTrace,
  LineStyle,
  MarkerSymbol,
  ScatterTrace,
} from './types';

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
  marker?: MarkerLook;
  box?: { color: string; opacity: number };
}

/** A box in pixels (x from the left, y from the top). */
export interface Rect {
  x: number;
  y: number;
  w: number;
  h: number;
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

export const num = (v: Data[number] | undefined): number => (typeof v === 'number' ? v : NaN);

export function strokeOf(line: LineStyle | undefined, fallback: string): Stroke {
  const width = line?.width ?? 2;
  const color = line?.color ?? fallback;
  const dash = dashArray(line?.dash, width);
  return dash ? { color, width, dash } : { color, width };
}

/** A scatter trace's mode: Plotly's default is lines and markers below 20 points, lines above. */
export function modeOf(t: ScatterTrace): { lines: boolean; markers: boolean } {
  const mode = t.mode ?? (t.x.length < 20 ? 'lines+markers' : 'lines');
  return { lines: mode.includes('lines'), markers: mode.includes('markers') };
}

/** A coordinate as written into path data: one decimal. */
const f = (v: number) => coordText(v, 1);

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
export function barsOf(t: ChartTrace, bargap: number): [number, number, number][] {
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

/** The spacing of evenly spaced cell centres (1 for a single cell). */
function cellStep(c: readonly number[]): number {
  return c.length > 1 ? (c[c.length - 1] - c[0]) / (c.length - 1) : 1;
}

/** The outer edges of evenly spaced cell centres. */
export function cellEdges(c: readonly number[]): [number, number] {
  if (c.length === 0) return [NaN, NaN];
  const d = cellStep(c);
  return [c[0] - d / 2, c[c.length - 1] + d / 2];
}

/** A heatmap's colour ramp: the diverging one for 'RdBu' (signed differences), else viridis. */
export function colormapOf(t: HeatmapTrace): Colormap {
  return t.colorscale === 'RdBu' ? DIVERGING : VIRIDIS;
}

export function colorOf(t: ChartTrace, i: number): string {
  const fallback = SERIES[i % SERIES.length];
  if (t.type === 'scatter' || t.type === undefined) {
    const mc = t.marker?.color;
    return t.line?.color ?? (typeof mc === 'string' ? mc : fallback);
  }
  if (t.type === 'heatmap') return fallback;
  const c = t.marker?.color;
  return typeof c === 'string' ? c : fallback;
}

export function swatchOf(t: ChartTrace, i: number): Swatch {
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

/** How one marker is drawn: its shape and size, its fill ('none' for an open symbol), its outline. */
export interface MarkerLook {
  symbol: MarkerSymbol;
  size: number;
  fill: string;
  stroke?: Stroke;
}

/**
 * Point i's marker: the trace's size and colour (one, or one per point). An open symbol is its
 * outline alone, in the marker's colour (2 px unless given); a filled one has an outline only when
 * the trace gives one.
 */
export function markerStyle(t: ScatterTrace, color: string, i: number): MarkerLook {
  const m = t.marker ?? {};
  const size = typeof m.size === 'number' ? m.size : Array.isArray(m.size) ? (m.size[i] ?? 6) : 6;
  const c = typeof m.color === 'string' ? m.color : Array.isArray(m.color) ? (m.color[i] ?? color) : color;
  const symbol = m.symbol ?? 'circle';
  const open = symbol === 'circle-open';
  const lw = m.line?.width ?? (open ? 2 : 0);
  const look = { symbol, size, fill: open ? 'none' : c };
  return lw > 0 ? { ...look, stroke: { color: open ? c : (m.line?.color ?? c), width: lw } } : look;
}

/** SVG path data of one marker of `symbol` and diameter `size` centred at (x, y). */
export function markerPath(symbol: MarkerSymbol, x: number, y: number, size: number): string {
  const r = size / 2;
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

/** What every trace's marks are drawn in: the axes, their names for the readout, and the mappings to pixels. */
interface Frame {
  x: Axis;
  y: Axis;
  names: AxisNames;
  px: (v: number) => number;
  py: (v: number) => number;
}

const fmt = (v: number) => formatNumber(v, 4);

/** The axes' names in the readout: their titles as plain text, else x and y. */
export interface AxisNames {
  x: string;
  y: string;
}

export function axisNames(xTitle: string, yTitle: string): AxisNames {
  return { x: plainText(xTitle) || 'x', y: plainText(yTitle) || 'y' };
}

/** A point's values as the readout writes them: "N 32, RMSE 0.0123" (4 significant digits). */
export function pairText(names: AxisNames, x: number, y: number): string {
  return `${names.x} ${fmt(x)}, ${names.y} ${fmt(y)}`;
}

/**
 * A bin [l, r) with as many significant digits as tell its ends apart (at least 4): a bin 10⁻⁸ wide
 * at 0.5 reads "[0.500000012, 0.500000022)", not "[0.5, 0.5)".
 */
export function binText(l: number, r: number): string {
  const scale = Math.max(Math.abs(l), Math.abs(r));
  const width = Math.abs(r - l);
  const digits = width > 0 && scale > 0 ? Math.ceil(Math.log10(scale / width)) + 2 : 4;
  const d = Math.min(15, Math.max(4, digits));
  return `[${formatNumber(l, d)}, ${formatNumber(r, d)})`;
}

/** A heatmap's cells, each coloured by its value on the trace's scale, and each a readout box. */
function heatmapMarks(t: HeatmapTrace, fr: Frame): { mark: Mark; boxes: { r: Rect; text: string }[] } {
  const map = colormapOf(t);
  const cells: { x: number; y: number; w: number; h: number; color: string }[] = [];
  const boxes: { r: Rect; text: string }[] = [];
  const dx = cellStep(t.x);
  const dy = cellStep(t.y);
  t.z.forEach((row, r) =>
    row.forEach((z, c) => {
      if (!Number.isFinite(z) || c >= t.x.length || r >= t.y.length) return;
      const xa = fr.px(t.x[c] - dx / 2);
      const xb = fr.px(t.x[c] + dx / 2);
      const ya = fr.py(t.y[r] - dy / 2);
      const yb = fr.py(t.y[r] + dy / 2);
      const rect = { x: Math.min(xa, xb), y: Math.min(ya, yb), w: Math.abs(xb - xa), h: Math.abs(yb - ya) };
      // a hairline of overlap hides the seams antialiasing leaves between cells
      const color = colorCss(normalizeValue(z, t.zmin, t.zmax), map);
      cells.push({ ...rect, w: rect.w + 0.5, h: rect.h + 0.5, color });
      boxes.push({ r: rect, text: `${pairText(fr.names, t.x[c], t.y[r])}: ${fmt(z)}` });
    }),
  );
  return { mark: { kind: 'cells', cells }, boxes };
}

/** A bar or histogram trace's bars as one path from the axis's foot, and each bar a readout box. */
function barMarks(
  t: BarTrace | HistogramTrace,
  fr: Frame,
  bargap: number,
): { d: string; boxes: { r: Rect; text: string }[] } {
  const y0 = fr.py(fr.y.kind === 'log' ? 10 ** fr.y.lo : 0);
  let d = '';
  const boxes: { r: Rect; text: string }[] = [];
  for (const [l, r, h] of barsOf(t, bargap)) {
    if (!Number.isFinite(h) || h === 0) continue;
    const xa = fr.px(l);
    const xb = fr.px(r);
    const yh = fr.py(h);
    if (![xa, xb, yh].every(Number.isFinite)) continue;
    d += `M${f(xa)} ${f(y0)}H${f(xb)}V${f(yh)}H${f(xa)}Z`;
    boxes.push({
      r: { x: Math.min(xa, xb), y: Math.min(y0, yh), w: Math.abs(xb - xa), h: Math.abs(yh - y0) },
      text: t.type === 'histogram' ? `${fmt(h)} in ${binText(l, r)}` : pairText(fr.names, (l + r) / 2, h),
    });
  }
  return { d, boxes };
}

/** A scatter trace's markers, one path per marker colour. */
function markerMarks(t: ScatterTrace, fr: Frame, color: string, opacity: number): Mark[] {
  const byColor = new Map<string, { d: string; look: MarkerLook }>();
  const n = Math.min(t.x.length, t.y.length);
  for (let k = 0; k < n; k++) {
    const px = fr.px(num(t.x[k]));
    const py = fr.py(num(t.y[k]));
    if (!Number.isFinite(px) || !Number.isFinite(py)) continue;
    const ms = markerStyle(t, color, k);
    if (!(ms.size > 0)) continue;
    const key = `${ms.fill}|${ms.stroke?.color ?? ''}`;
    const g = byColor.get(key) ?? { d: '', look: ms };
    g.d += markerPath(ms.symbol, px, py, ms.size);
    byColor.set(key, g);
  }
  return [...byColor.values()].map(({ d, look }) => ({
    kind: 'markers' as const,
    d,
    fill: look.fill,
    ...(look.stroke ? { stroke: look.stroke } : {}),
    opacity,
  }));
}

/** Every trace's marks and readout targets, in drawing order. */
export function drawTraces(
  traces: readonly ChartTrace[],
  frame: { x: Axis; y: Axis; xTitle: string; yTitle: string },
  bargap: number,
): { marks: Mark[]; targets: Target[] } {
  const { x, y } = frame;
  const fr: Frame = {
    x,
    y,
    names: axisNames(frame.xTitle, frame.yTitle),
    px: (v) => unitsToPx(x, toUnits(x.kind, v)),
    py: (v) => unitsToPx(y, toUnits(y.kind, v)),
  };
  const marks: Mark[] = [];
  const targets: Target[] = [];
  // the previous scatter trace's points, for a fill to it ('tonexty')
  let prevLine: [number, number][] = [];

  traces.forEach((t, i) => {
    const color = colorOf(t, i);
    const name = plainText(t.name ?? '');
    const opacity = t.opacity ?? 1;
    if (t.type === 'heatmap') {
      const { mark, boxes } = heatmapMarks(t, fr);
      marks.push(mark);
      targets.push({ kind: 'boxes', name, color, boxes });
      return;
    }
    if (t.type === 'bar' || t.type === 'histogram') {
      const { d, boxes } = barMarks(t, fr, bargap);
      marks.push({ kind: 'area', d, color, opacity: opacity * (t.marker?.opacity ?? 1) });
      targets.push({ kind: 'boxes', name, color, boxes });
      return;
    }
    // scatter: the line through its points, breaking at gaps
    const pts: [number, number][] = [];
    const tx: number[] = [];
    const ty: number[] = [];
    const tt: (string | undefined)[] = [];
    let d = '';
    let pen = false;
    for (let k = 0; k < Math.min(t.x.length, t.y.length); k++) {
      const a = num(t.x[k]);
      const b = num(t.y[k]);
      const px = fr.px(a);
      const py = fr.py(b);
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
      const ring = [...pts, ...[...prevLine].reverse()].map(([a, b], k) => `${k ? 'L' : 'M'}${f(a)} ${f(b)}`);
      marks.push({ kind: 'area', d: `${ring.join('')}Z`, color: t.fillcolor ?? color, opacity });
    }
    const stroke = strokeOf(t.line, color);
    if (lines && stroke.width > 0 && d) marks.push({ kind: 'line', d, opacity, ...stroke });
    if (markers) marks.push(...markerMarks(t, fr, color, opacity * (t.marker?.opacity ?? 1)));
    prevLine = pts;
    if (t.hoverinfo !== 'skip' && pts.length)
      targets.push({
        kind: 'points',
        name,
        color,
        px: pts.map((p) => p[0]),
        py: pts.map((p) => p[1]),
        x: tx,
        y: ty,
        text: tt,
      });
  });
  return { marks, targets };
}
