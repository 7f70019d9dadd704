/**
 * A per-pixel Welch t-test between two images rendered by two estimators (Jung, Hanika and
 * Dachsbacher, JCGT 2020): every pixel holds a sample mean, an unbiased sample variance and a
 * sample count per image, and gets its own two-sided p-value. The images agree (both estimators
 * converge to the same picture) when no pixel's p falls below the Šidák-corrected level
 * 1 − (1 − α)^(1/m) over the m pixels tested, so the chance of a false alarm anywhere in an
 * unbiased image is α.
 */
import { sidakAlpha } from './sidak';
import { welchStatistic } from './ttest';
import { pixelMeanVariance } from '../image/stdDevImage';

/** Per-pixel statistics of one image stack: mean, unbiased variance s² of the samples, count. */
export interface PixelStats {
  mean: ArrayLike<number>;
  variance: ArrayLike<number>;
  count: ArrayLike<number>;
}

/**
 * Per-pixel statistics of K independent renders of one image (each pixel of each a mean of its own
 * samples, so the K values of a pixel are independent and identically distributed): their mean,
 * unbiased variance and K.
 */
export function pixelStatsOfRuns(runs: readonly ArrayLike<number>[]): PixelStats {
  const { mean, variance } = pixelMeanVariance(runs);
  return { mean, variance, count: new Float64Array(mean.length).fill(runs.length) };
}

/** The map and its verdict. */
export interface WelchMap {
  /** Two-sided p per pixel; NaN where the test cannot run (fewer than 2 samples, non-finite). */
  pValues: Float64Array;
  /** Pixels with a p-value (m). */
  tested: number;
  /** Pixels whose p is below the corrected level. */
  rejected: number;
  /** The smallest p over the tested pixels (NaN when none was tested). */
  minP: number;
  alpha: number;
  /** Per-pixel level after the Šidák correction over `tested` pixels. */
  sidakAlpha: number;
  /** True when no pixel is rejected (and at least one was tested). */
  pass: boolean;
}

/** The Welch t-test map of two images of equal pixel count at overall significance α. */
export function welchMap(a: PixelStats, b: PixelStats, alpha = 0.01): WelchMap {
  const n = a.mean.length;
  if (b.mean.length !== n || a.variance.length !== n || b.variance.length !== n)
    throw new RangeError(`Welch map needs images of one size: ${n} pixels against ${b.mean.length}`);
  const pValues = new Float64Array(n);
  let tested = 0;
  let minP = Infinity;
  const sa = { mean: 0, variance: 0, n: 0 };
  const sb = { mean: 0, variance: 0, n: 0 };
  for (let i = 0; i < n; i++) {
    sa.mean = a.mean[i];
    sa.variance = a.variance[i];
    sa.n = a.count[i];
    sb.mean = b.mean[i];
    sb.variance = b.variance[i];
    sb.n = b.count[i];
    const p = welchStatistic(sa, sb).pValue;
    pValues[i] = p;
    if (Number.isNaN(p)) continue;
    tested++;
    if (p < minP) minP = p;
  }
  const level = sidakAlpha(alpha, tested);
  let rejected = 0;
  for (let i = 0; i < n; i++) if (pValues[i] < level) rejected++;
  return {
    pValues,
    tested,
    rejected,
    minP: tested ? minP : NaN,
    alpha,
    sidakAlpha: level,
    pass: tested > 0 && rejected === 0,
  };
}
