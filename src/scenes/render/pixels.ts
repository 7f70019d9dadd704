/**
 * From the accumulated sums to what the canvas shows: each pixel's mean (sum / count) as linear
 * radiance, clipped to [0, 1] and encoded with the sRGB transfer curve (IEC 61966-2-1) into 8-bit
 * RGBA (grey: the renderer has one channel). A pixel that has no sample yet is drawn black.
 * Also the numbers the page reads off the image: samples per pixel reached and mean brightness.
 */
import { srgbByte } from '../../core/image/srgb';

/** Write the image (sum / count per pixel, row-major) into `rgba` (4 bytes per pixel). */
export function copyPixels(sum: Float64Array, count: Uint32Array, rgba: Uint8ClampedArray): void {
  for (let k = 0, o = 0; k < sum.length; k++, o += 4) {
    const b = count[k] > 0 ? srgbByte(sum[k] / count[k]) : 0;
    rgba[o] = b;
    rgba[o + 1] = b;
    rgba[o + 2] = b;
    rgba[o + 3] = 255;
  }
}

/** Write an image of pixel means (linear radiance, row-major) into `rgba` as copyPixels does. */
export function copyMeans(means: ArrayLike<number>, rgba: Uint8ClampedArray): void {
  for (let k = 0, o = 0; k < means.length; k++, o += 4) {
    const b = Number.isFinite(means[k]) ? srgbByte(means[k]) : 0;
    rgba[o] = b;
    rgba[o + 1] = b;
    rgba[o + 2] = b;
    rgba[o + 3] = 255;
  }
}

/** What the page reports of the image so far. */
export interface ImageStats {
  /** Samples every pixel has (the smallest count). */
  spp: number;
  /** Mean of the pixels' means (linear radiance), NaN before every pixel has a sample. */
  mean: number;
}

export function imageStats(sum: Float64Array, count: Uint32Array): ImageStats {
  let spp = Infinity;
  let total = 0;
  for (let k = 0; k < sum.length; k++) {
    const c = count[k];
    if (c < spp) spp = c;
    if (c > 0) total += sum[k] / c;
  }
  if (sum.length === 0) return { spp: 0, mean: NaN };
  return { spp, mean: spp > 0 ? total / sum.length : NaN };
}

/** The image's means (sum / count; NaN where a pixel has no sample), for the error against a reference. */
export function pixelMeans(sum: Float64Array, count: Uint32Array): Float64Array {
  const out = new Float64Array(sum.length);
  for (let k = 0; k < sum.length; k++) out[k] = count[k] > 0 ? sum[k] / count[k] : NaN;
  return out;
}
