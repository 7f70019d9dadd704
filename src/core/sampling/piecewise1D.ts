/**
 * Tabulated (piecewise-constant) 1D distribution: sampling by inversion of its CDF.
 * Source: pbrt-v4 `PiecewiseConstant1D` (util/sampling.h, §A.4.1 "Piecewise-Constant 1D
 * Functions"), except that negative, non-finite or all-zero tables are reported as errors
 * instead of silently taking |f|: a density the user typed must be a density.
 */

/** Result of {@link validateDensity}. */
export type DensityCheck =
  { ok: true } | { ok: false; reason: 'negative' | 'nonfinite' | 'zero'; index: number };

/**
 * Check that tabulated density values can define a distribution: every value finite and ≥ 0, and
 * not all zero. Reports the first offending index (index −1 for 'zero').
 * Domain: any array-like of numbers.
 */
export function validateDensity(values: ArrayLike<number>): DensityCheck {
  let any = false;
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    if (!Number.isFinite(v)) return { ok: false, reason: 'nonfinite', index: i };
    if (v < 0) return { ok: false, reason: 'negative', index: i };
    if (v > 0) any = true;
  }
  return any ? { ok: true } : { ok: false, reason: 'zero', index: -1 };
}

/** Plain-language message for a failed {@link validateDensity} check. */
export function densityErrorMessage(check: DensityCheck, what = 'density'): string {
  if (check.ok) return '';
  switch (check.reason) {
    case 'negative':
      return `the ${what} is negative at table entry ${check.index}; a pdf must be ≥ 0 everywhere`;
    case 'nonfinite':
      return `the ${what} is not finite (∞ or NaN) at table entry ${check.index}; it cannot be normalized`;
    case 'zero':
      return `the ${what} is zero everywhere, so it cannot be normalized`;
  }
}

/** Error thrown by the tabulated distributions for an invalid density table. */
export class DensityError extends Error {
  readonly reason: 'negative' | 'nonfinite' | 'zero';
  readonly index: number;
  constructor(check: Extract<DensityCheck, { ok: false }>, what?: string) {
    super(densityErrorMessage(check, what));
    this.name = 'DensityError';
    this.reason = check.reason;
    this.index = check.index;
  }
}

/**
 * Binary search: largest i in [0, size − 2] with pred(i) true, assuming pred is true then false
 * (pbrt-v4 `FindInterval`). Returns 0 if pred(0) is false.
 */
export function findInterval(size: number, pred: (i: number) => boolean): number {
  let first = 1;
  let sz = size - 2;
  while (sz > 0) {
    const half = sz >>> 1;
    const middle = first + half;
    const r = pred(middle);
    first = r ? middle + 1 : first;
    sz = r ? sz - (half + 1) : half;
  }
  const i = first - 1;
  return i < 0 ? 0 : i > size - 2 ? size - 2 : i;
}

/**
 * Piecewise-constant density on [min, max] proportional to f: bin i covers
 * [min + i·Δ, min + (i+1)·Δ), Δ = (max − min)/count, with value f[i].
 * Measure: per unit length of x. `integral` = Σ f[i]·Δ is the normalization constant's inverse
 * (pdf = f / integral).
 */
export class PiecewiseConstant1D {
  /** The table values f[i] (copied). */
  readonly func: Float64Array;
  /** CDF at bin edges: cdf[0] = 0, cdf[count] = 1. */
  readonly cdf: Float64Array;
  /**
   * ∫ f(x) dx over [min, max] (1/integral is the normalization constant). For absurd tables it may
   * underflow to 0 or overflow to ∞; the pdf and sampling stay exact regardless.
   */
  readonly integral: number;
  /** Normalized density of each bin, f[i]/integral, computed without overflow. */
  readonly pdfs: Float64Array;
  /** Number of bins. */
  readonly count: number;
  readonly min: number;
  readonly max: number;

  /**
   * @param f density values, ≥ 0 and finite, not all zero (throws {@link DensityError} otherwise)
   * @param min, max the interval, min < max (throws RangeError otherwise)
   * @param opts.allowZero accept an all-zero table (uniform CDF, pdf 0; used for empty rows of
   *   {@link PiecewiseConstant2D})
   */
  constructor(f: ArrayLike<number>, min: number, max: number, opts: { allowZero?: boolean } = {}) {
    if (!(Number.isFinite(min) && Number.isFinite(max) && min < max)) {
      throw new RangeError(`interval [${min}, ${max}] must be finite with min < max`);
    }
    if (f.length < 1) throw new RangeError('a tabulated density needs at least one value');
    const check = validateDensity(f);
    if (!check.ok && !(check.reason === 'zero' && opts.allowZero)) throw new DensityError(check);
    const n = f.length;
    this.count = n;
    this.min = min;
    this.max = max;
    this.func = Float64Array.from(f);
    // Work with w = f / max(f) so that neither the sum nor the integral can overflow or underflow
    // (a table like [1e-320] on a short interval, or [1e308, 1e308], still normalizes exactly).
    let maxF = 0;
    for (let i = 0; i < n; i++) if (this.func[i] > maxF) maxF = this.func[i];
    const cdf = new Float64Array(n + 1);
    const pdfs = new Float64Array(n);
    const dx = (max - min) / n;
    if (maxF === 0) {
      for (let i = 1; i <= n; i++) cdf[i] = i / n;
      this.integral = 0;
    } else {
      for (let i = 1; i <= n; i++) cdf[i] = cdf[i - 1] + this.func[i - 1] / maxF;
      const sum = cdf[n]; // in [1, n]
      for (let i = 1; i <= n; i++) cdf[i] = cdf[i] / sum;
      for (let i = 0; i < n; i++) pdfs[i] = this.func[i] / maxF / sum / dx;
      this.integral = maxF * sum * dx;
      // entries after the last non-zero bin are exactly 1, so rounding can never let u < 1 select
      // a trailing empty bin
      let last = n - 1;
      while (last > 0 && this.func[last] === 0) last--;
      for (let i = last + 1; i <= n; i++) cdf[i] = 1;
    }
    cdf[n] = 1;
    this.cdf = cdf;
    this.pdfs = pdfs;
  }

  /** CDF at the left edge of bin i (i = 0 … count; cdfAt(count) = 1). Clamped index. */
  cdfAt(i: number): number {
    const k = Math.max(0, Math.min(this.count, Math.floor(i)));
    return this.cdf[k];
  }

  /** Bin containing x (clamped to [0, count − 1]). */
  offsetOf(x: number): number {
    const c = ((x - this.min) / (this.max - this.min)) * this.count;
    const o = Math.floor(c);
    return o < 0 ? 0 : o > this.count - 1 ? this.count - 1 : o;
  }

  /**
   * Sample x ∈ [min, max] with density pdf(x) from u ∈ [0, 1) by inverting the CDF inside the
   * chosen bin. Also returns that pdf and the bin index. Bins with f = 0 are never chosen.
   * Source: pbrt-v4 `PiecewiseConstant1D::Sample`.
   */
  sample(u: number): { x: number; pdf: number; offset: number } {
    const uu = u > 0 ? (u < 1 ? u : 1) : 0;
    const cdf = this.cdf;
    const o = findInterval(cdf.length, (i) => cdf[i] <= uu);
    let du = uu - cdf[o];
    const w = cdf[o + 1] - cdf[o];
    if (w > 0) du /= w;
    if (du > 1) du = 1;
    const pdf = this.pdfs[o];
    const x = this.min + ((o + du) / this.count) * (this.max - this.min);
    return { x: x < this.max ? x : this.max, pdf, offset: o };
  }

  /**
   * Batched {@link sample}: for each u[i] write x into xOut[i] and, if given, the pdf into
   * pdfOut[i]. Caller-owned buffers, no allocation.
   */
  sampleMany(u: Float64Array, xOut: Float64Array, pdfOut?: Float64Array, count = u.length): void {
    const cdf = this.cdf;
    const n = this.count;
    const span = this.max - this.min;
    for (let k = 0; k < count; k++) {
      const uu = u[k] > 0 ? (u[k] < 1 ? u[k] : 1) : 0;
      let lo = 0;
      let hi = n; // invariant: cdf[lo] <= uu, answer in [lo, hi)
      while (hi - lo > 1) {
        const mid = (lo + hi) >>> 1;
        if (cdf[mid] <= uu) lo = mid;
        else hi = mid;
      }
      const w = cdf[lo + 1] - cdf[lo];
      let du = w > 0 ? (uu - cdf[lo]) / w : uu - cdf[lo];
      if (du > 1) du = 1;
      const x = this.min + ((lo + du) / n) * span;
      xOut[k] = x < this.max ? x : this.max;
      if (pdfOut) pdfOut[k] = this.pdfs[lo];
    }
  }

  /** Density at x (per unit length): f[bin]/integral inside [min, max], 0 outside. */
  pdf(x: number): number {
    if (!(x >= this.min && x <= this.max)) return 0;
    return this.pdfs[this.offsetOf(x)];
  }

  /**
   * Inverse of {@link sample}: the u ∈ [0, 1] that maps to x (the CDF at x). x outside
   * [min, max] is clamped (giving 0 or 1); NaN gives 0. Source: pbrt-v4 `PiecewiseConstant1D::Invert`.
   */
  invert(x: number): number {
    if (!(x > this.min)) return 0;
    if (x >= this.max) return 1;
    const c = ((x - this.min) / (this.max - this.min)) * this.count;
    const o = Math.min(this.count - 1, Math.floor(c));
    const delta = c - o;
    return this.cdf[o] + delta * (this.cdf[o + 1] - this.cdf[o]);
  }
}
