/**
 * The curves of the error-against-distance plot, for float64 (Precision.tsx) and float32
 * (float32Traces.ts): per arithmetic, the median error of Δ (lines and markers) and of t-hit
 * (dotted) for each method, and the thin dashed guides of how the errors grow. The colours are
 * CSS variables of ray-sphere.css, one value per theme, each ≥ 3 : 1 on the page and the panels
 * (Plot resolves them when it draws).
 */
import type { LineStyle, MarkerStyle, PlotTrace } from '../../../ui';
import type { ErrorSeries } from '../errorSeries';

export const ERROR_COLOURS = {
  naive: 'var(--rs-naive)',
  stable: 'var(--rs-stable)',
  naiveF32: 'var(--rs-naive-f32)',
  stableF32: 'var(--rs-stable-f32)',
  /** The guides u (D/r)², u (D/r) and u₃₂ (D/r)². */
  guide: 'var(--rs-guide)',
  guide2: 'var(--rs-guide-2)',
  guideF32: 'var(--rs-guide-f32)',
} as const;

/** A curve of the error plot: a line, with markers when given. */
export function curve(
  x: number[],
  y: number[],
  name: string,
  line: LineStyle,
  marker?: MarkerStyle,
): PlotTrace {
  return marker ? { x, y, name, mode: 'lines+markers', line, marker } : { x, y, name, mode: 'lines', line };
}

/** A dashed guide y = min(1, f(D)) over the series' distances. */
export function guide(s: ErrorSeries, f: (D: number) => number, name: string, color: string): PlotTrace {
  const y = s.dist.map((D) => Math.min(1, f(D)));
  return curve(s.dist, y, name, { color, width: 1, dash: 'dash' });
}

/**
 * The four curves of one arithmetic: textbook and robust Δ (markers), textbook and robust t-hit
 * (dotted); `suffix` follows each name (", float32"), `marker` styles the Δ curves' markers.
 */
export function methodCurves(
  s: ErrorSeries,
  colours: { naive: string; stable: string },
  suffix = '',
  marker: MarkerStyle = { size: 4 },
): PlotTrace[] {
  const { naive, stable } = colours;
  return [
    curve(s.dist, s.discNaive, `textbook Δ${suffix}`, { color: naive }, marker),
    curve(s.dist, s.discStable, `robust Δ${suffix}`, { color: stable }, marker),
    curve(s.dist, s.hitNaive, `textbook t<sub>hit</sub>${suffix}`, { color: naive, dash: 'dot' }),
    curve(s.dist, s.hitStable, `robust t<sub>hit</sub>${suffix}`, { color: stable, dash: 'dot' }),
  ];
}
