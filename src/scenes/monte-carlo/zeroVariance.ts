/**
 * Zero variance to rounding: when an estimator's terms are all equal in exact arithmetic (p ∝ f),
 * their spread is rounding noise, and the page says "zero variance" instead of printing noise.
 */

/**
 * Rounding allowance of {@link zeroToRounding}, in units of ε·|mean|. Each term f(x)/p(x) carries a
 * few roundings (the sample, f, p, the division), so terms that are equal in exact arithmetic differ
 * by a few ulps, and Welford's update adds a few more to s; any spread a real pdf leaves (a tabulated
 * p ∝ |f| leaves about 10⁻⁴ of the mean) is many orders of magnitude above this.
 */
export const ZERO_SPREAD_ULPS = 64;

/**
 * Whether a spread (the terms' standard deviation s) is zero to rounding: exactly 0, or at most
 * ZERO_SPREAD_ULPS · ε · |mean|, relative to the magnitude of the estimate and to machine epsilon
 * (so the verdict does not change when f is scaled by any power of two). Not finite: false.
 */
export function zeroToRounding(spread: number, mean: number): boolean {
  if (spread === 0) return true;
  return (
    Number.isFinite(spread) &&
    Number.isFinite(mean) &&
    spread <= ZERO_SPREAD_ULPS * Number.EPSILON * Math.abs(mean)
  );
}

/** Whether an estimate's terms have zero variance to rounding (s = √variance against the estimate). */
export function estimateHasZeroVariance(e: { n: number; variance: number; estimate: number }): boolean {
  return e.n > 1 && zeroToRounding(Math.sqrt(Math.max(0, e.variance)), e.estimate);
}

/** Values of a strategy's convergence-series error at rounding level at every N (zero variance). */
export function atRoundingLevel(values: ArrayLike<number>, reference: number): boolean {
  const tiny = Math.abs(reference) * 1e-15 || 1e-300;
  let any = false;
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    if (!Number.isFinite(v)) continue;
    any = true;
    if (v > tiny * 100) return false;
  }
  return any;
}
