/**
 * The per-pixel standard deviation of an estimator's image, measured from K independent runs of it
 * (same samples per pixel, different random streams): sᵢ = √(1/(K − 1) Σₖ (xᵢₖ − x̄ᵢ)²). It shows
 * where an estimator is noisy without a reference image, and its square averaged over the image
 * is the expected MSE of one run when the estimator is unbiased (Celarek, Jakob, Wimmer and
 * Lehtinen, "Quantifying the Error of Light Transport Algorithms", EGSR 2019, measure error this
 * way from independent runs).
 */

/**
 * Per-pixel mean and unbiased sample variance over K runs of equal length (the variance NaN for one
 * run), by Welford's update, one pass over the runs.
 */
export function pixelMeanVariance(runs: readonly ArrayLike<number>[]): {
  mean: Float64Array;
  variance: Float64Array;
} {
  const k = runs.length;
  const n = k ? runs[0].length : 0;
  for (const r of runs)
    if (r.length !== n) throw new RangeError(`runs must have one size: ${n} values against ${r.length}`);
  const mean = new Float64Array(n);
  const m2 = new Float64Array(n);
  for (let j = 0; j < k; j++) {
    const r = runs[j];
    for (let i = 0; i < n; i++) {
      const x = r[i];
      const d = x - mean[i];
      mean[i] += d / (j + 1);
      m2[i] += d * (x - mean[i]);
    }
  }
  const variance = new Float64Array(n);
  for (let i = 0; i < n; i++) variance[i] = k > 1 ? m2[i] / (k - 1) : NaN;
  return { mean, variance };
}

/** Per-pixel sample standard deviation over K ≥ 2 runs of equal length; NaN where a run is not finite. */
export function stdDevImage(runs: readonly ArrayLike<number>[]): Float64Array {
  const k = runs.length;
  if (k < 2) throw new RangeError(`a standard-deviation image needs at least 2 runs, not ${k}`);
  return pixelMeanVariance(runs).variance.map(Math.sqrt);
}

/** The mean of the squared per-pixel standard deviations: the expected MSE of one run if unbiased. */
export function meanVariance(sd: ArrayLike<number>): number {
  let s = 0;
  let m = 0;
  for (let i = 0; i < sd.length; i++) {
    const v = sd[i];
    if (!Number.isFinite(v)) continue;
    s += v * v;
    m++;
  }
  return m ? s / m : NaN;
}
