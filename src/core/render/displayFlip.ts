/**
 * FLIP of a rendered image against its reference as a viewer sees them: both grey images of linear
 * radiance shown as the app shows them (clipped, sRGB-encoded 8-bit levels, ./../image/srgb), then
 * LDR-FLIP (../image/flip, Andersson et al. 2020) at the given pixels per degree. Where the
 * reference has no value (NaN: a pixel with no exact reference), the reference takes the render's
 * own value there, so that the pixel counts as no error, and the mean is taken over the pixels
 * that have a reference only.
 */
import { DEFAULT_PPD, flipErrorMap, type RgbImage } from '../image/flip';
import { srgbByte } from '../image/srgb';

/** Three equal channels of each value's display level, in [0, 1]. */
function greyImage(values: ArrayLike<number>, res: number): RgbImage {
  const data = new Float64Array(3 * res * res);
  for (let k = 0; k < res * res; k++)
    data[3 * k] = data[3 * k + 1] = data[3 * k + 2] = srgbByte(values[k]) / 255;
  return { width: res, height: res, data };
}

/**
 * The mean FLIP error of `image` against `reference` (res × res, row-major, linear radiance) over
 * the pixels whose reference is a number; NaN when none is.
 */
export function displayFlipMean(
  image: ArrayLike<number>,
  reference: ArrayLike<number>,
  res: number,
  ppd = DEFAULT_PPD,
): number {
  const ref = new Float64Array(res * res);
  let known = 0;
  for (let k = 0; k < ref.length; k++) {
    const has = Number.isFinite(reference[k]);
    ref[k] = has ? reference[k] : image[k];
    if (has) known++;
  }
  if (known === 0) return NaN;
  const map = flipErrorMap(greyImage(ref, res), greyImage(image, res), ppd);
  let sum = 0;
  for (let k = 0; k < map.length; k++) if (Number.isFinite(reference[k])) sum += map[k];
  return sum / known;
}
