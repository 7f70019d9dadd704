/**
 * A chart laid out: from traces and a layout (./types) and the figure's size, everything the SVG
 * draws, in pixels: the plot area and margins that fit the tick labels, titles, legend and colour
 * bar; the axes and their ticks; every trace's marks (./marks); and the pointer's readout. Pure
 * (text is measured through the given function), so tests read a chart's marks against its data
 * without a browser.
 */
import { colorCss, normalizeValue } from '../../core/colormap';
import { niceTicks, tickLabel } from '../axis';
import { coordText } from '../chartScale';
import { autoRange, makeTicks, toUnits, unitsToPx, type Axis, type AxisKind, type Tick } from './axes';
import {
  axisNames,
  barsOf,
  cellEdges,
  colormapOf,
  drawTraces,
  modeOf,
  num,
  pairText,
  plainText,
  strokeOf,
  swatchOf,
  type Mark,
  type Rect,
  type Stroke,
  type Swatch,
  type Target,
} from './marks';
import type { AxisSpec, ChartLayout, ChartTrace, HeatmapTrace, LegendSpec } from './types';

export interface ChartStyle {
  /** Font size (px) of titles and the legend. */
  font: number;
  /** Font size (px) of tick labels. */
  tick: number;
  /** Font size (px) of the 2s and 5s between a log axis's decades; 0.8 × `tick` when absent. */
  minorTick?: number;
  /** Width (px) of `text` set at `size` px. */
  measure: (text: string, size: number) => number;
  /** Width (px) of what sits over the figure's top right corner (the plot's tool buttons): the top row of a legend above the plot stops short of it. */
  topRight?: number;
}

/** A zoomed view: the axes' ranges in axis units (log10 on a log axis), instead of their own. */
export interface View {
  x?: readonly [number, number];
  y?: readonly [number, number];
}

export interface LegendItem {
  text: string;
  /** Left end of the swatch and the row's middle (px). */
  x: number;
  y: number;
  swatch: Swatch;
}

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
/** A legend entry's swatch length and the gap after an entry (px). */
const SWATCH = 30;
const ITEM_GAP = 16;
/** The colour bar's width (px). */
const COLORBAR = 14;

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
  // (each takes axis units; a value an axis cannot show is NaN and left out)
  const growX = (u: number) => {
    if (Number.isFinite(u)) x = x ? [Math.min(x[0], u), Math.max(x[1], u)] : [u, u];
  };
  const growY = (u: number) => {
    if (Number.isFinite(u)) y = y ? [Math.min(y[0], u), Math.max(y[1], u)] : [u, u];
  };
  const addX = (v: number) => growX(toUnits(kx, v));
  const addY = (v: number) => growY(toUnits(ky, v));
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
        // a point counts only where both axes can show it
        const ux = toUnits(kx, num(t.x[i]));
        const uy = toUnits(ky, num(t.y[i]));
        if (Number.isFinite(ux) && Number.isFinite(uy)) {
          growX(ux);
          growY(uy);
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

/** Lay the legend's entries out in rows of at most `width` px (one per row when vertical); offsets from the rows' start. */
function flowLegend(
  entries: { text: string; swatch: Swatch }[],
  width: number,
  vertical: boolean,
  style: ChartStyle,
  firstRow = width,
): { rows: { text: string; swatch: Swatch; dx: number }[][]; widest: number } {
  const rows: { text: string; swatch: Swatch; dx: number }[][] = [];
  let dx = 0;
  let widest = 0;
  for (const e of entries) {
    const w = SWATCH + 6 + style.measure(plainText(e.text), style.font);
    if (!rows.length || vertical || (dx > 0 && dx + w > (rows.length === 1 ? firstRow : width))) {
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
 * The title's centre: over the plot area, moved left as far as it must be to end before what sits
 * over the figure's top right corner (the tool buttons), and never past the figure's left edge.
 */
function titleX(text: string, plot: Rect, width: number, style: ChartStyle): number {
  const half = style.measure(plainText(text), style.font * 1.1) / 2;
  const centre = plot.x + plot.w / 2;
  const end = width - (style.topRight ?? 0) - 4;
  return Math.max(half + 4, Math.min(centre, end - half));
}

/** An axis without its ticks: its range (axis units) from px0 to px1, swapped when reversed. */
function axisSpan(
  kind: AxisKind,
  range: readonly [number, number],
  from: number,
  to: number,
  reversed: boolean,
): Omit<Axis, 'ticks'> {
  const [px0, px1] = reversed ? [to, from] : [from, to];
  return { kind, lo: Math.min(range[0], range[1]), hi: Math.max(range[0], range[1]), px0, px1 };
}

/** The legend's entries placed: above the plot from the figure's left edge, below it, or inside it. */
function placeLegend(
  rows: ReturnType<typeof flowLegend>,
  place: 'above' | 'below' | 'inside',
  spec: LegendSpec,
  at: { plot: Rect; titleH: number; bottom: number; rowH: number },
): { items: LegendItem[]; box: Rect } {
  const { plot, rowH } = at;
  const h = rows.rows.length * rowH;
  const w = rows.widest;
  // above or below the plot, rows run from the figure's left edge (they wrap at its right)
  let bx = 6;
  let by: number;
  if (place === 'above') by = at.titleH + 2;
  else if (place === 'below') by = plot.y + plot.h + at.bottom - (h + 4);
  else {
    const right = spec.xanchor === 'right';
    bx = plot.x + (spec.x ?? 0.02) * plot.w + (right ? -(w + 8) : 4);
    by = plot.y + (1 - (spec.y ?? 0.98)) * plot.h + (spec.yanchor === 'bottom' ? -h - 4 : 4);
  }
  const items: LegendItem[] = [];
  rows.rows.forEach((row, r) =>
    row.forEach((e) =>
      items.push({ text: e.text, swatch: e.swatch, x: bx + e.dx, y: by + r * rowH + rowH / 2 }),
    ),
  );
  return { items, box: { x: bx - 4, y: by, w: w + 8, h } };
}

/** The layout's line shapes as paths: data coordinates on the axes, 'paper' ones as fractions of the plot area. */
function shapesOf(shapes: ChartLayout['shapes'], plot: Rect, x: Axis, y: Axis): ChartModel['shapes'] {
  const out: ChartModel['shapes'] = [];
  const f = (v: number) => coordText(v, 1);
  for (const s of shapes ?? []) {
    const px = (v: number) => (s.xref === 'paper' ? plot.x + v * plot.w : unitsToPx(x, toUnits(x.kind, v)));
    const py = (v: number) =>
      s.yref === 'paper' ? plot.y + (1 - v) * plot.h : unitsToPx(y, toUnits(y.kind, v));
    const pts = [px(s.x0), py(s.y0), px(s.x1), py(s.y1)];
    if (!pts.every(Number.isFinite)) continue;
    out.push({ d: `M${f(pts[0])} ${f(pts[1])}L${f(pts[2])} ${f(pts[3])}`, ...strokeOf(s.line, 'var(--fg)') });
  }
  return out;
}

/** A heatmap's colour bar: its ticks on zmin … zmax, the room it takes right of the plot, and its drawing once placed. */
function colourBar(heat: HeatmapTrace | undefined, style: ChartStyle) {
  if (!heat) return { width: 0, place: () => null };
  const { ticks, step } = niceTicks(heat.zmin, heat.zmax, 4);
  const labels = ticks.map((v) => tickLabel(v, step));
  const width = 10 + COLORBAR + 4 + Math.max(0, ...labels.map((s) => style.measure(s, style.tick)));
  const place = (plot: Rect): ChartModel['colorbar'] => {
    const r = { x: plot.x + plot.w + 10, y: plot.y, w: COLORBAR, h: plot.h };
    const map = colormapOf(heat);
    const stops = Array.from({ length: 11 }, (_, k) => ({ t: k / 10, color: colorCss(k / 10, map) }));
    const inside = ticks.filter((v) => v >= heat.zmin && v <= heat.zmax);
    return {
      r,
      stops,
      ticks: inside.map((v) => ({
        px: r.y + r.h * (1 - normalizeValue(v, heat.zmin, heat.zmax)),
        label: tickLabel(v, step),
      })),
    };
  };
  return { width, place };
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
  const xReversed = layout.xaxis?.autorange === 'reversed';
  const yReversed = layout.yaxis?.autorange === 'reversed';
  const bargap = layout.bargap ?? (traces.some((t) => t.type === 'bar') ? 0.2 : 0);
  const ext = extents(traces, layout, kx, ky, bargap);
  const xr = view.x ?? layout.xaxis?.range ?? autoRange(ext.x, kx, ext.markers ? 0.03 : 0);
  const yr = view.y ?? layout.yaxis?.range ?? autoRange(ext.y, ky, ext.bars ? 0.08 : 0.06, ext.bars);
  const xTitle = layout.xaxis?.title?.text ?? '';
  const yTitle = layout.yaxis?.title?.text ?? '';
  const lineH = (size: number) => Math.ceil(size * 1.3);
  const bar = colourBar(
    traces.find((t): t is HeatmapTrace => t.type === 'heatmap' && t.showscale === true),
    style,
  );

  // the legend's rows: a legend above or below wraps at the figure's width (its top row short of
  // what sits over the top right corner), one inside at most 90 % of the plot's
  const entries = legendEntries(traces, layout);
  const place = legendPlace(layout.legend);
  const vertical = layout.legend?.orientation === 'v';
  const rowH = Math.max(lineH(style.font), 18);
  const titleH = layout.title?.text ? lineH(style.font * 1.1) + 6 : 0;
  const tickH = lineH(style.tick);
  const firstRow = place === 'above' && !layout.title?.text ? width - 12 - (style.topRight ?? 0) : width - 12;
  const legend = flowLegend(entries, width - 12, vertical, style, firstRow);
  const legendH = entries.length && place !== 'inside' ? legend.rows.length * rowH + 4 : 0;

  // top and bottom first (they do not depend on the labels' widths), then the y axis, whose
  // labels set the left margin, then the x axis, whose last label may reach past the plot's right end
  const top = Math.max(m.t, titleH + (place === 'above' ? legendH : 0) + Math.ceil(style.tick / 2) + 4);
  const bottom =
    Math.max(m.b, tickH + 6 + (xTitle ? lineH(style.font) + 4 : 0) + 2) +
    (place === 'below' ? legendH + 4 : 0);
  const ph = Math.max(20, height - top - bottom);
  const yBase = axisSpan(ky, yr, top + ph, top, yReversed);
  const y: Axis = { ...yBase, ticks: makeTicks(yBase, Y_SPACING, () => style.tick * 1.2) };
  const minor = style.minorTick ?? style.tick * 0.8;
  const yLabelW = Math.max(0, ...y.ticks.map((t) => style.measure(t.label, t.minor ? minor : style.tick)));
  const left = Math.max(m.l, Math.ceil(yLabelW + 8 + (yTitle ? lineH(style.font) + 6 : 0) + 2));
  const xm = (s: string) => style.measure(s, style.tick);
  let right = m.r + bar.width;
  let xBase = axisSpan(kx, xr, left, left + Math.max(20, width - left - right), xReversed);
  let xt = makeTicks(xBase, X_SPACING, xm);
  const plotEnd = Math.max(xBase.px0, xBase.px1);
  const overhang = Math.max(0, ...xt.map((t) => t.px + xm(t.label) / 2 - plotEnd));
  if (overhang > right - bar.width) {
    right = bar.width + Math.ceil(overhang) + 2;
    xBase = axisSpan(kx, xr, left, left + Math.max(20, width - left - right), xReversed);
    xt = makeTicks(xBase, X_SPACING, xm);
  }
  const x: Axis = { ...xBase, ticks: xt };
  const plot: Rect = { x: left, y: top, w: Math.abs(xBase.px1 - xBase.px0), h: ph };

  const rows = place === 'inside' ? flowLegend(entries, plot.w * 0.9, vertical, style) : legend;
  const placed = entries.length
    ? placeLegend(rows, place, layout.legend ?? {}, { plot, titleH, bottom, rowH })
    : null;
  const title = layout.title?.text;
  return {
    width,
    height,
    plot,
    x,
    y,
    xTitle,
    yTitle,
    title: title ? { text: title, x: titleX(title, plot, width, style), y: lineH(style.font * 1.1) } : null,
    ...drawTraces(traces, { x, y, xTitle, yTitle }, bargap),
    shapes: shapesOf(layout.shapes, plot, x, y),
    legend: {
      items: placed?.items ?? [],
      rowHeight: rowH,
      box: place === 'inside' ? (placed?.box ?? null) : null,
    },
    colorbar: bar.place(plot),
  };
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
  // the nearest point first, its words written once found
  let best: { d: number; t: Extract<Target, { kind: 'points' }>; k: number } | null = null;
  for (const t of model.targets) {
    if (t.kind !== 'points') continue;
    for (let k = 0; k < t.px.length; k++) {
      const d = Math.hypot(t.px[k] - px, t.py[k] - py);
      if (d <= reach && (!best || d < best.d)) best = { d, t, k };
    }
  }
  if (best) {
    const { t, k } = best;
    const text = t.text[k];
    return {
      x: t.px[k],
      y: t.py[k],
      color: t.color,
      lines: [
        ...(t.name ? [t.name] : []),
        pairText(axisNames(model.xTitle, model.yTitle), t.x[k], t.y[k]),
        ...(text ? [plainText(text)] : []),
      ],
    };
  }
  for (let i = model.targets.length - 1; i >= 0; i--) {
    const t = model.targets[i];
    if (t.kind !== 'boxes') continue;
    for (const b of t.boxes)
      if (px >= b.r.x && px <= b.r.x + b.r.w && py >= b.r.y && py <= b.r.y + b.r.h)
        return { x: px, y: py, color: t.color, lines: [...(t.name ? [t.name] : []), b.text] };
  }
  return null;
}
