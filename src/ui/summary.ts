/**
 * One sentence that says what a plotted series shows, for the plot's accessible description: its
 * trend, its extremes with where they are, its last value and, on log–log axes, the fitted slope
 * ("|error| falls as N⁻⁰·⁵⁰"). Pure, no DOM.
 */
import { fitLogLogSlope } from '../core/estimators/slope';
import { superscript } from './axis';
import { formatSignificant } from './format';

export interface SummaryOptions {
  xLabel: string;
  yLabel: string;
  /** Fit and state the slope of log y against log x (points with x ≤ 0 or y ≤ 0 are left out of the fit). */
  logLog?: boolean;
  /** How a number is written (default: 3 significant digits, "×10⁻⁵" style). */
  format?: (v: number) => string;
}

const defaultFormat = (v: number) => formatSignificant(v, 3, 'times');

/** A minus sign, not a hyphen, in front of negative numbers a screen reader should read as such. */
function withMinus(s: string): string {
  return s.replace(/^-/, '−');
}

/** An exponent written with superscripts, the decimal point raised as "·": −0.50 → "⁻⁰·⁵⁰". */
export function superscriptExponent(e: number, digits = 2): string {
  const s = e.toFixed(digits).replace(/^-/, '−');
  return superscript(s).replace('.', '·');
}

/**
 * The sentence (see module doc). Only pairs where both x and y are finite count; with none the
 * sentence says there is no data.
 */
export function summarizeSeries(
  xs: ArrayLike<number>,
  ys: ArrayLike<number>,
  { xLabel, yLabel, logLog = false, format = defaultFormat }: SummaryOptions,
): string {
  const f = (v: number) => withMinus(format(v));
  const px: number[] = [];
  const py: number[] = [];
  const n0 = Math.min(xs.length, ys.length);
  for (let i = 0; i < n0; i++) {
    const x = xs[i]!;
    const y = ys[i]!;
    if (Number.isFinite(x) && Number.isFinite(y)) {
      px.push(x);
      py.push(y);
    }
  }
  const n = px.length;
  if (n === 0) return `${yLabel} against ${xLabel}: no data to show.`;
  const at = (i: number) => `${f(py[i]!)} at ${xLabel} = ${f(px[i]!)}`;
  if (n === 1) return `${yLabel} against ${xLabel}: one point, ${at(0)}.`;

  let iMin = 0;
  let iMax = 0;
  let ups = 0;
  let downs = 0;
  for (let i = 1; i < n; i++) {
    if (py[i]! < py[iMin]!) iMin = i;
    if (py[i]! > py[iMax]!) iMax = i;
    if (py[i]! > py[i - 1]!) ups++;
    else if (py[i]! < py[i - 1]!) downs++;
  }
  const lo = py[iMin]!;
  const hi = py[iMax]!;
  const range = hi - lo;
  const scale = Math.max(Math.abs(lo), Math.abs(hi));
  const parts: string[] = [];
  if (range <= 1e-12 * scale || range === 0) {
    parts.push(`${yLabel} is flat at ${f(lo)} from ${xLabel} = ${f(px[0]!)} to ${f(px[n - 1]!)}`);
  } else {
    const first = py[0]!;
    const last = py[n - 1]!;
    const net = last - first;
    const steady = ups === 0 || downs === 0;
    let trend: string;
    if (Math.abs(net) < 0.05 * range) trend = `${yLabel} ends about where it starts`;
    else if (net > 0) trend = steady ? `${yLabel} rises` : `${yLabel} rises overall`;
    else trend = steady ? `${yLabel} falls` : `${yLabel} falls overall`;
    parts.push(`${trend} from ${at(0)} to ${at(n - 1)}`);
    parts.push(`minimum ${at(iMin)}`);
    parts.push(`maximum ${at(iMax)}`);
  }
  parts.push(`last value ${at(n - 1)}`);
  let sentence = `${parts.join('; ')}.`;
  if (logLog) {
    const fit = fitLogLogSlope(px, py);
    if (Number.isFinite(fit.slope)) {
      const verb = fit.slope < 0 ? 'falls' : fit.slope > 0 ? 'rises' : 'stays level';
      sentence += ` On log–log axes ${yLabel} ${verb} as ${xLabel}${superscriptExponent(fit.slope)} (fitted slope ${withMinus(fit.slope.toFixed(2))} over ${fit.points} points).`;
    }
  }
  return sentence;
}
