/**
 * Root-mean-square error over independent runs, with bands. The RMSE at N is
 * √(1/R Σ_r (⟨I⟩_r − I)²): for an unbiased estimator it equals the true standard deviation of the
 * estimator, which shrinks like N^-1/2 for independent samples and faster for stratified / QMC
 * points (Owen, "Monte Carlo theory, methods and examples", ch. 15–17; pbrt-v4 §8.2).
 */
import { ConvergenceSeries } from './convergence';

/** RMSE of the estimates[start..end) about `exact`; NaN when empty. */
export function rmse(estimates: ArrayLike<number>, exact: number, start = 0, end = estimates.length): number {
  let s = 0;
  let c = 0;
  for (let i = start; i < end; i++) {
    const d = estimates[i] - exact;
    s += d * d;
    c++;
  }
  return c > 0 ? Math.sqrt(s / c) : NaN;
}

/**
 * Value at quantile q ∈ [0, 1] of values[start..end), linear interpolation between order statistics
 * (type 7, the default of R and NumPy). Sorts a copy; NaN when empty.
 */
export function quantile(values: ArrayLike<number>, q: number, start = 0, end = values.length): number {
  const m = end - start;
  if (m <= 0) return NaN;
  const s = new Float64Array(m);
  for (let i = 0; i < m; i++) s[i] = values[start + i];
  s.sort();
  const h = (m - 1) * Math.min(1, Math.max(0, q));
  const lo = Math.floor(h);
  const hi = Math.min(m - 1, lo + 1);
  return s[lo] + (h - lo) * (s[hi] - s[lo]);
}

/**
 * Collects the convergence series of R independent runs on the same checkpoints and summarises
 * them per checkpoint: RMSE, mean estimate, and quantile bands of |error|. Memory R × K doubles.
 */
export class RmseAccumulator {
  readonly n: Float64Array;
  /** |error| of run r at checkpoint k, at [r * K + k]. */
  readonly errors: Float64Array;
  readonly estimates: Float64Array;
  runs = 0;

  constructor(
    checkpoints: ArrayLike<number>,
    readonly exact: number,
    readonly maxRuns: number,
  ) {
    this.n = Float64Array.from(checkpoints);
    this.errors = new Float64Array(maxRuns * this.n.length).fill(NaN);
    this.estimates = new Float64Array(maxRuns * this.n.length).fill(NaN);
  }

  /** Add one run's series (must share the checkpoints). Ignored once maxRuns is reached. */
  addRun(series: ConvergenceSeries): void {
    if (this.runs >= this.maxRuns) return;
    const K = this.n.length;
    const o = this.runs * K;
    for (let k = 0; k < K; k++) {
      this.estimates[o + k] = series.estimate[k];
      this.errors[o + k] = Math.abs(series.estimate[k] - this.exact);
    }
    this.runs++;
  }

  /** Summary per checkpoint: RMSE, mean estimate, and the [qLo, qHi] quantiles of |error|. */
  summary(
    qLo = 0.1,
    qHi = 0.9,
  ): { n: Float64Array; rmse: Float64Array; mean: Float64Array; lo: Float64Array; hi: Float64Array } {
    const K = this.n.length;
    const R = this.runs;
    const out = {
      n: this.n.slice(),
      rmse: new Float64Array(K).fill(NaN),
      mean: new Float64Array(K).fill(NaN),
      lo: new Float64Array(K).fill(NaN),
      hi: new Float64Array(K).fill(NaN),
    };
    const col = new Float64Array(R);
    const est = new Float64Array(R);
    for (let k = 0; k < K; k++) {
      let m = 0;
      for (let r = 0; r < R; r++) {
        const e = this.errors[r * K + k];
        const x = this.estimates[r * K + k];
        if (!Number.isFinite(e)) continue;
        col[m] = e;
        est[m] = x;
        m++;
      }
      if (m === 0) continue;
      out.rmse[k] = rmse(est, this.exact, 0, m);
      let s = 0;
      for (let i = 0; i < m; i++) s += est[i];
      out.mean[k] = s / m;
      out.lo[k] = quantile(col, qLo, 0, m);
      out.hi[k] = quantile(col, qHi, 0, m);
    }
    return out;
  }
}
