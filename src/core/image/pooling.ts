/**
 * Pooled figures of an error map, as rendering papers report FLIP: the mean, the weighted
 * percentiles (the value below which a given share of the total error lies, not of the pixels),
 * the extremes, and the weighted histogram. The weighted percentile follows NVIDIA's FLIP tool:
 * values sorted ascending, the first whose running sum exceeds the share of the total.
 */

export interface PooledError {
  mean: number;
  weightedMedian: number;
  weightedQuartile1: number;
  weightedQuartile3: number;
  min: number;
  max: number;
  /** Pixel counts in `bins` equal bins over [0, 1] (a value of exactly 1 falls in the last). */
  histogram: Uint32Array;
}

/** The value below which `share` (0 … 1) of the sum of `sorted` (ascending, non-negative) lies. */
export function weightedPercentile(sorted: Float64Array, share: number, total: number): number {
  let running = 0;
  for (let i = 0; i < sorted.length; i++) {
    running += sorted[i];
    if (running > share * total) return sorted[i];
  }
  return sorted.length ? sorted[sorted.length - 1] : NaN;
}

/** Pool an error map with values in [0, 1]. Empty maps give NaN figures and an empty histogram. */
export function poolError(map: ArrayLike<number>, bins = 100): PooledError {
  const n = map.length;
  const sorted = Float64Array.from(map).sort();
  let sum = 0;
  for (let i = 0; i < n; i++) sum += sorted[i];
  const histogram = new Uint32Array(bins);
  for (let i = 0; i < n; i++) {
    const v = sorted[i];
    if (!(v >= 0 && v <= 1)) continue;
    histogram[Math.min(bins - 1, Math.floor(v * bins))]++;
  }
  return {
    mean: n ? sum / n : NaN,
    weightedMedian: weightedPercentile(sorted, 0.5, sum),
    weightedQuartile1: weightedPercentile(sorted, 0.25, sum),
    weightedQuartile3: weightedPercentile(sorted, 0.75, sum),
    min: n ? sorted[0] : NaN,
    max: n ? sorted[n - 1] : NaN,
    histogram,
  };
}
