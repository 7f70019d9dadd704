/**
 * The marginal densities of a lobe as curves a reader can follow: where each puts its mass (peak,
 * median, flat or not) and its CDF, by trapezoids on a fine grid (the lobes give their marginal
 * densities, not always their CDFs); and the samples' CDF from a histogram. Pure, no DOM.
 */

/** Where a marginal density puts its mass: its peak, its median and whether it is flat. */
export interface MarginalShape {
  peak: number;
  median: number;
  flat: boolean;
  lo: number;
  hi: number;
}

/** The shape of a density f on [lo, hi] from a fine grid (trapezoids for the median). */
export function marginalShape(f: (x: number) => number, lo: number, hi: number, m = 400): MarginalShape {
  const xs = new Float64Array(m + 1);
  const ys = new Float64Array(m + 1);
  let peak = lo;
  let yMax = -Infinity;
  let yMin = Infinity;
  for (let k = 0; k <= m; k++) {
    // the end of a half-open support (φ < 2π) is read just inside it
    const x = k === m ? hi - (hi - lo) * 1e-12 : lo + ((hi - lo) * k) / m;
    const y = Math.max(0, f(x));
    xs[k] = x;
    ys[k] = Number.isFinite(y) ? y : 0;
    if (ys[k] > yMax * (1 + 1e-9)) {
      yMax = ys[k];
      peak = x;
    }
    if (k > 0 && k < m) yMin = Math.min(yMin, ys[k]);
  }
  let total = 0;
  for (let k = 0; k < m; k++) total += 0.5 * (ys[k] + ys[k + 1]) * (xs[k + 1] - xs[k]);
  let acc = 0;
  let median = (lo + hi) / 2;
  for (let k = 0; k < m; k++) {
    const piece = 0.5 * (ys[k] + ys[k + 1]) * (xs[k + 1] - xs[k]);
    if (total > 0 && acc + piece >= total / 2) {
      const f0 = piece > 0 ? (total / 2 - acc) / piece : 0;
      median = xs[k] + f0 * (xs[k + 1] - xs[k]);
      break;
    }
    acc += piece;
  }
  return { peak, median, flat: yMax <= yMin * 1.001, lo, hi };
}

/** The CDF P(x) = ∫ f from lo to x on m + 1 points, scaled to end at 1 (trapezoids). */
export function cdfCurve(
  f: (x: number) => number,
  lo: number,
  hi: number,
  m = 200,
): { x: Float64Array; y: Float64Array } {
  const x = new Float64Array(m + 1);
  const y = new Float64Array(m + 1);
  let prev = 0;
  for (let k = 0; k <= m; k++) {
    x[k] = lo + ((hi - lo) * k) / m;
    const xe = k === m ? hi - (hi - lo) * 1e-12 : x[k];
    const v = Math.max(0, f(xe));
    const fx = Number.isFinite(v) ? v : 0;
    if (k > 0) y[k] = y[k - 1] + 0.5 * (prev + fx) * (x[k] - x[k - 1]);
    prev = fx;
  }
  const total = y[m];
  if (total > 0) for (let k = 0; k <= m; k++) y[k] /= total;
  return { x, y };
}

/** The samples' CDF at the right edge of each bin of a density histogram (bin width w, lower end lo). */
export function histogramCdf(
  density: ArrayLike<number>,
  w: number,
  lo: number,
): { x: Float64Array; y: Float64Array } {
  const m = density.length;
  const x = new Float64Array(m + 1);
  const y = new Float64Array(m + 1);
  x[0] = lo;
  for (let b = 0; b < m; b++) {
    x[b + 1] = lo + (b + 1) * w;
    y[b + 1] = y[b] + density[b] * w;
  }
  return { x, y };
}
