/**
 * The per-pixel standard deviation of an estimator's image, measured from K independent runs of it
 * (same samples per pixel, different random streams): sᵢ = √(1/(K − 1) Σₖ (xᵢₖ − x̄ᵢ)²). It shows
 * where an estimator is noisy without a reference image, and its square averaged over the image
 * is the expected MSE of one run when the estimator is unbiased (Celarek, Jakob, Wimmer and
 * Lehtinen, "Quantifying the Error of Light Transport Algorithms", EGSR 2019, measure error this
 * way from independent runs). Welford's update per pixel, one pass over the runs.
 */

/** Per-pixel sample standard deviation over K ≥ 2 runs of equal length; NaN where a run is not finite. */
export function stdDevImage(runs: readonly ArrayLike<number>[]): Float64Array {
  const k = runs.length;
  if (k < 2) throw new RangeError(`a standard-deviation image needs at least 2 runs, not ${k}`);
  const n = runs[0].length;
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
  const out = new Float64Array(n);
  for (let i = 0; i < n; i++) out[i] = Math.sqrt(m2[i] / (k - 1));
  return out;
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
