/**
 * Do two renderers make the same image within their noise? Each pixel of each image is a mean of n
 * samples with its standard error (se² = s²/n); the two renderers draw different random streams, so
 * under the hypothesis that they compute the same estimator the per-pixel difference, scaled,
 *
 *     zᵢ = (aᵢ − bᵢ) / √(se_a,ᵢ² + se_b,ᵢ² + δᵢ²),
 *
 * is centred on 0. δᵢ = ROUNDING_ULPS · 2⁻²³ · max(|aᵢ|, |bᵢ|, s) counts float32 rounding as noise
 * of a few ulps of the pixel's value, or of the image's scale s (the mean of max(|aᵢ|, |bᵢ|) over the
 * image) where the pixel is far darker: a pixel whose samples are all one value (the furnace under
 * cosine sampling returns 1 at every sample) is not held to more digits than float32 has, and a
 * glossy lobe's tail of 10⁻²⁶⁶, which float32 rounds to 0, is not a difference.
 *
 * The test: pixels with noise (either side's se > δ) give T = Σzᵢ / √(Σzᵢ²), the self-normalized sum.
 * With the same estimator on both sides each zᵢ is symmetric about 0 (swapping the two renderers
 * flips its sign), and for symmetric independent terms T is at most as spread as a standard normal
 * (Efron, "Student's t-test under symmetry conditions", JASA 1969), whatever the shape of the
 * pixels' distributions: runs of 16 samples of a small light are far from normal, so Σzᵢ² against
 * a χ² with one degree per pixel would raise false alarms. T² is compared with χ² of one degree of
 * freedom (the two-sided normal test): a renderer that is too bright or too dark over the image
 * fails. Pixels without noise on either side must agree within δ. Verdict: pass when p ≥ α and
 * every quiet pixel agrees.
 */
import { chi2UpperTail } from '../verify/chi2';

/** Float32 rounding counted as noise: this many ulps of the pixel's value. */
export const ROUNDING_ULPS = 8;
/** The test's level. */
export const COMPARE_ALPHA = 0.001;

const F32_EPS = 2 ** -23;

/** An image as per-pixel means and squared standard errors. */
export interface PixelMoments {
  mean: ArrayLike<number>;
  se2: ArrayLike<number>;
}

export interface RendererComparison {
  /** Per-pixel z (0 where a pixel agrees exactly; NaN where either mean is not finite). */
  z: Float64Array;
  /** Pixels with noise on either side (they enter T) and pixels without (they must agree within δ). */
  noisy: number;
  quiet: number;
  /** Quiet pixels that differ by more than δ. */
  quietMismatches: number;
  /** T = Σz / √(Σz²) over the noisy pixels, T², and its p (χ², one degree of freedom). */
  t: number;
  chi2: number;
  p: number;
  maxAbsZ: number;
  alpha: number;
  pass: boolean;
}

/** Per-pixel mean and se² from sums: Σx, Σx², n samples (se² = s²/n, s² the unbiased variance, ≥ 0). */
export function momentsFromSums(
  sum: ArrayLike<number>,
  sumSq: ArrayLike<number>,
  n: number,
): { mean: Float64Array; se2: Float64Array } {
  const mean = new Float64Array(sum.length);
  const se2 = new Float64Array(sum.length);
  for (let k = 0; k < sum.length; k++) {
    const m = sum[k] / n;
    mean[k] = m;
    se2[k] = n > 1 ? Math.max(0, (sumSq[k] - n * m * m) / (n - 1)) / n : Infinity;
  }
  return { mean, se2 };
}

/** Compare two images pixel by pixel (see the module comment). */
export function compareRenderers(
  a: PixelMoments,
  b: PixelMoments,
  alpha = COMPARE_ALPHA,
): RendererComparison {
  const n = a.mean.length;
  if (b.mean.length !== n)
    throw new RangeError(`images of different sizes: ${n} and ${b.mean.length} pixels`);
  const z = new Float64Array(n);
  let scale = 0,
    finite = 0;
  for (let k = 0; k < n; k++) {
    const v = Math.max(Math.abs(a.mean[k]), Math.abs(b.mean[k]));
    if (Number.isFinite(v)) {
      scale += v;
      finite++;
    }
  }
  scale = finite > 0 ? scale / finite : 0;
  let noisy = 0,
    quiet = 0,
    quietMismatches = 0,
    sz = 0,
    sz2 = 0,
    maxAbsZ = 0;
  for (let k = 0; k < n; k++) {
    const ma = a.mean[k],
      mb = b.mean[k];
    if (!Number.isFinite(ma) || !Number.isFinite(mb)) {
      z[k] = NaN;
      continue;
    }
    const delta = ROUNDING_ULPS * F32_EPS * Math.max(Math.abs(ma), Math.abs(mb), scale);
    const noise = a.se2[k] + b.se2[k];
    const d = ma - mb;
    const zk = d === 0 ? 0 : d / Math.sqrt(noise + delta * delta);
    z[k] = zk;
    if (Math.abs(zk) > maxAbsZ) maxAbsZ = Math.abs(zk);
    if (noise > delta * delta) {
      noisy++;
      sz += zk;
      sz2 += zk * zk;
    } else {
      quiet++;
      if (Math.abs(d) > delta) quietMismatches++;
    }
  }
  const t = sz2 > 0 ? sz / Math.sqrt(sz2) : 0;
  const chi2 = t * t;
  const p = sz2 > 0 ? chi2UpperTail(chi2, 1) : 1;
  return {
    z,
    noisy,
    quiet,
    quietMismatches,
    t,
    chi2,
    p,
    maxAbsZ,
    alpha,
    pass: p >= alpha && quietMismatches === 0,
  };
}
