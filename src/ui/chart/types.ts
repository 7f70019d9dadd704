/**
 * What a plot is given: its traces and its layout, in the shape of Plotly's figure schema (the
 * names and meanings of plotly.js's `data` and `layout` attributes, so that they read as the
 * widely documented ones), narrowed to the part this project draws. Anything outside these types
 * is a type error at the call site rather than an option silently ignored.
 *
 * Reference for the attribute meanings: plotly.js's figure reference (plotly.com/javascript/reference).
 */

/** A number, or null for a gap (a line breaks there; no marker, no bar). */
export type Datum = number | null;
export type Data = readonly Datum[] | Float64Array | Float32Array;

/** Line dashes: the named ones, or a CSS dash list in px ("5px,2px,1px,2px"). */
export type Dash =
  'solid' | 'dash' | 'dot' | 'dashdot' | 'longdash' | 'longdashdot' | `${number}px,${string}`;

export interface LineStyle {
  /** A CSS colour or `var(--…)` (resolved when drawn). */
  color?: string;
  /** Stroke width in px (0: no line). Default 2. */
  width?: number;
  dash?: Dash;
}

export type MarkerSymbol = 'circle' | 'circle-open' | 'square' | 'diamond' | 'x';

export interface MarkerStyle {
  /** One colour, or one per point. */
  color?: string | readonly string[];
  /** Diameter in px, or one per point (0 hides the point). Default 6. */
  size?: number | readonly number[];
  symbol?: MarkerSymbol;
  opacity?: number;
  /** The marker's outline (an open symbol's stroke). */
  line?: { width?: number; color?: string };
}

interface TraceBase {
  /** The legend's and the hover label's name; may carry <sub>…</sub> / <sup>…</sup>. */
  name?: string;
  /** False keeps the trace out of the legend. */
  showlegend?: boolean;
  /** Traces of one group share one legend entry (the first shown trace's). */
  legendgroup?: string;
  /** 'skip': the pointer's readout passes over this trace. */
  hoverinfo?: 'skip' | 'all';
  /** The whole trace's opacity, 0–1. */
  opacity?: number;
}

export interface ScatterTrace extends TraceBase {
  type?: 'scatter';
  x: Data;
  y: Data;
  /** Default: 'lines+markers' for fewer than 20 points, else 'lines' (as Plotly). */
  mode?: 'lines' | 'markers' | 'lines+markers';
  line?: LineStyle;
  marker?: MarkerStyle;
  /** A line of text per point, added to the pointer's readout of that point. */
  text?: readonly string[];
  /** 'tonexty': fill between this line and the previous trace's. */
  fill?: 'none' | 'tonexty';
  fillcolor?: string;
}

export interface BarTrace extends TraceBase {
  type: 'bar';
  /** Bar centres. */
  x: Data;
  /** Bar heights (from 0). */
  y: Data;
  /** Bar width in x units; default: the smallest gap between centres times (1 − bargap). */
  width?: number;
  marker?: { color?: string; opacity?: number };
}

export interface HistogramTrace extends TraceBase {
  type: 'histogram';
  /** The samples counted. */
  x: Data;
  /** The bins: [start, end) cut in steps of size (the last bin closed). */
  xbins: { start: number; end: number; size: number };
  marker?: { color?: string; opacity?: number };
}

export interface HeatmapTrace extends TraceBase {
  type: 'heatmap';
  /** Cell centres along x (columns) and y (rows), evenly spaced. */
  x: readonly number[];
  y: readonly number[];
  /** z[row][column]. */
  z: readonly (readonly number[])[];
  zmin: number;
  zmax: number;
  /** 'Viridis' (values) or 'RdBu' (signed differences, blue below the middle). */
  colorscale: 'Viridis' | 'RdBu';
  /** Swap the scale's ends ('RdBu' reversed: red above the middle). */
  reversescale?: boolean;
  /** Draw the colour bar beside the plot. */
  showscale?: boolean;
}

export type ChartTrace = ScatterTrace | BarTrace | HistogramTrace | HeatmapTrace;

export interface AxisSpec {
  type?: 'linear' | 'log';
  title?: { text: string };
  /** The axis's range; on a log axis in decades (log10 of the ends), as Plotly. */
  range?: readonly [number, number];
  /** 'reversed': the axis runs from its largest value to its smallest. */
  autorange?: 'reversed';
  /** Kept for the Plotly schema's sake: exponents are always written as powers of ten. */
  exponentformat?: 'power';
  tickfont?: { size?: number };
}

/**
 * Where the legend goes, in fractions of the plot area (x from its left, y from its bottom), as
 * Plotly's legend: y > 1 above it (the default), y < 0 below it, inside it otherwise.
 */
export interface LegendSpec {
  orientation?: 'h' | 'v';
  x?: number;
  y?: number;
  xanchor?: 'left' | 'right';
  yanchor?: 'top' | 'bottom';
  bgcolor?: string;
}

export interface ShapeSpec {
  type: 'line';
  x0: number;
  x1: number;
  y0: number;
  y1: number;
  /** 'paper': the coordinate is a fraction of the plot area (0 bottom or left, 1 top or right). */
  xref?: 'x' | 'paper';
  yref?: 'y' | 'paper';
  line?: LineStyle;
}

export interface Margin {
  l: number;
  r: number;
  t: number;
  b: number;
}

export interface ChartLayout {
  /** A title above the plot area (centred). */
  title?: { text: string };
  /** The least margins (px) around the plot area; they grow to fit tick labels, titles and legends. */
  margin?: Partial<Margin>;
  showlegend?: boolean;
  legend?: LegendSpec;
  xaxis?: AxisSpec;
  yaxis?: AxisSpec;
  /** Gap between bars as a fraction of a bar's slot (default 0.2). */
  bargap?: number;
  /** 'overlay': histograms drawn over each other (the only way this project draws two). */
  barmode?: 'overlay';
  shapes?: readonly ShapeSpec[];
}
