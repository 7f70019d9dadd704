/**
 * Convergence series: the running estimate, its absolute error and its standard error recorded at
 * log-spaced sample counts N, without storing the samples (O(checkpoints) memory, one pass).
 * Used for the exam's Q4(d) graph: the estimate as N grows, |error| against N on log-log axes.
 * Source: pbrt-v4 §2.1.4 (error and convergence, O(N^-1/2)); Owen, "Monte Carlo theory, methods
 * and examples" ch. 2 (the standard error) and ch. 15–17 (QMC's faster rates).
 */

/**
 * Log-spaced sample counts from nMin to nMax (both included), about `perDecade` per decade,
 * strictly increasing integers. Domain: 1 ≤ nMin ≤ nMax, perDecade ≥ 1. Returns a Float64Array.
 */
export function logSpacedCounts(nMax: number, perDecade = 10, nMin = 1): Float64Array {
  nMax = Math.max(1, Math.floor(nMax));
  nMin = Math.max(1, Math.min(Math.floor(nMin), nMax));
  const out: number[] = [];
  const l0 = Math.log10(nMin);
  const l1 = Math.log10(nMax);
  const steps = Math.max(1, Math.ceil((l1 - l0) * perDecade));
  let last = 0;
  for (let k = 0; k <= steps; k++) {
    const n = k === steps ? nMax : Math.round(10 ** (l0 + ((l1 - l0) * k) / steps));
    if (n > last && n <= nMax) {
      out.push(n);
      last = n;
    }
  }
  if (out[out.length - 1] !== nMax) out.push(nMax);
  return Float64Array.from(out);
}

/**
 * Running statistics of a stream of per-sample estimator terms Yᵢ (f/p), recorded at the
 * checkpoints. `estimate[k]` = mean of the first `n[k]` terms, `absError[k]` = |estimate − exact|,
 * `stderr[k]` = s/√N at that point (NaN for N < 2). Mean and M₂ are updated by Welford's rule.
 * Non-finite terms are counted in `invalid` and skipped (they do not advance N).
 */
export class ConvergenceSeries {
  /** Sample counts at which the series is recorded (strictly increasing). */
  readonly n: Float64Array;
  readonly estimate: Float64Array;
  readonly absError: Float64Array;
  readonly stderr: Float64Array;
  /** Number of checkpoints recorded so far. */
  recorded = 0;
  /** Terms consumed so far. */
  count = 0;
  mean = 0;
  m2 = 0;
  invalid = 0;

  /**
   * @param checkpoints strictly increasing counts (e.g. {@link logSpacedCounts}); copied
   * @param exact the true integral, for |error| (NaN if unknown: absError is then NaN)
   */
  constructor(
    checkpoints: ArrayLike<number>,
    readonly exact: number,
  ) {
    this.n = Float64Array.from(checkpoints);
    const k = this.n.length;
    this.estimate = new Float64Array(k).fill(NaN);
    this.absError = new Float64Array(k).fill(NaN);
    this.stderr = new Float64Array(k).fill(NaN);
  }

  /** Feed terms[start..end) (batched; records every checkpoint crossed). */
  push(terms: ArrayLike<number>, start = 0, end = terms.length): void {
    let n = this.count;
    let mean = this.mean;
    let m2 = this.m2;
    let k = this.recorded;
    const K = this.n.length;
    let next = k < K ? this.n[k] : Infinity;
    for (let i = start; i < end; i++) {
      const y = terms[i];
      if (!Number.isFinite(y)) {
        this.invalid++;
        continue;
      }
      n++;
      const d = y - mean;
      mean += d / n;
      m2 += d * (y - mean);
      if (n === next) {
        this.estimate[k] = mean;
        this.absError[k] = Math.abs(mean - this.exact);
        this.stderr[k] = n > 1 ? Math.sqrt(m2 / (n - 1) / n) : NaN;
        k++;
        next = k < K ? this.n[k] : Infinity;
      }
    }
    this.count = n;
    this.mean = mean;
    this.m2 = m2;
    this.recorded = k;
  }

  /**
   * Record checkpoint k directly from a separate estimate made with exactly n[k] samples (used for
   * stratified sampling, whose prefix is not itself stratified, so each N needs its own set).
   */
  record(k: number, estimate: number, stderr: number): void {
    this.estimate[k] = estimate;
    this.absError[k] = Math.abs(estimate - this.exact);
    this.stderr[k] = stderr;
    if (k + 1 > this.recorded) this.recorded = k + 1;
  }
}
