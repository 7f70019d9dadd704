/**
 * Running mean and variance by Welford's update, mergeable across batches and workers.
 *
 * Source: B. P. Welford, "Note on a method for calculating corrected sums of squares and products",
 * Technometrics 4(3), 1962; the merge is Chan, Golub & LeVeque, "Updating formulae and a pairwise
 * algorithm for computing sample variances" (1979). pbrt-v4 `util/stats.h` `VarianceEstimator`
 * (Add, Merge, Mean, Variance, RelativeVariance) is the model followed here.
 *
 * Why not Σx and Σx²: with mean μ ≫ σ the difference Σx²/N − μ² cancels catastrophically; Welford
 * keeps M₂ = Σ(xᵢ − x̄)² directly and loses no digits.
 */
export class Welford {
  /** Number of values added, N. */
  count = 0;
  /** Running mean x̄ of the values added (0 while empty). */
  mean = 0;
  /** Running sum of squared deviations M₂ = Σ(xᵢ − x̄)². */
  m2 = 0;

  /** Add one value x (any finite double; a non-finite x makes mean and variance non-finite). */
  add(x: number): void {
    const n = ++this.count;
    const d = x - this.mean;
    this.mean += d / n;
    this.m2 += d * (x - this.mean);
  }

  /**
   * Add values[start..end) in one pass (batched kernel: no allocation).
   * Domain: start ≤ end ≤ values.length.
   */
  addArray(values: ArrayLike<number>, start = 0, end = values.length): void {
    let n = this.count;
    let mean = this.mean;
    let m2 = this.m2;
    for (let i = start; i < end; i++) {
      const x = values[i];
      n++;
      const d = x - mean;
      mean += d / n;
      m2 += d * (x - mean);
    }
    this.count = n;
    this.mean = mean;
    this.m2 = m2;
  }

  /**
   * Merge another accumulator into this one (Chan et al. 1979): the result equals adding all of
   * `other`'s values here, in any order, up to rounding. `other` is unchanged.
   */
  merge(other: Welford): void {
    if (other.count === 0) return;
    if (this.count === 0) {
      this.count = other.count;
      this.mean = other.mean;
      this.m2 = other.m2;
      return;
    }
    const n = this.count + other.count;
    const d = other.mean - this.mean;
    this.mean += (d * other.count) / n;
    this.m2 += other.m2 + ((d * d * this.count) / n) * other.count;
    this.count = n;
  }

  /** Unbiased sample variance s² = M₂ / (N − 1); 0 when N < 2 (pbrt's convention). */
  variance(): number {
    return this.count > 1 ? this.m2 / (this.count - 1) : 0;
  }

  /** Population variance M₂ / N; 0 when empty. */
  populationVariance(): number {
    return this.count > 0 ? this.m2 / this.count : 0;
  }

  /**
   * Standard error of the mean, s / √N: the standard deviation of x̄ as an estimator of E[x].
   * NaN when N < 2 (no spread can be measured from one value).
   */
  standardError(): number {
    return this.count > 1 ? Math.sqrt(this.variance() / this.count) : NaN;
  }

  /** Relative variance s² / x̄² (pbrt `RelativeVariance`); 0 when N < 2 or x̄ = 0. */
  relativeVariance(): number {
    return this.count < 2 || this.mean === 0 ? 0 : this.variance() / (this.mean * this.mean);
  }

  /** Reset to empty. */
  reset(): void {
    this.count = 0;
    this.mean = 0;
    this.m2 = 0;
  }

  /** An independent copy. */
  clone(): Welford {
    const w = new Welford();
    w.count = this.count;
    w.mean = this.mean;
    w.m2 = this.m2;
    return w;
  }

  /** Plain-data snapshot (for posting between workers). */
  toJSON(): { count: number; mean: number; m2: number } {
    return { count: this.count, mean: this.mean, m2: this.m2 };
  }

  /** Rebuild from a {@link Welford.toJSON} snapshot. */
  static from(s: { count: number; mean: number; m2: number }): Welford {
    const w = new Welford();
    w.count = s.count;
    w.mean = s.mean;
    w.m2 = s.m2;
    return w;
  }
}
