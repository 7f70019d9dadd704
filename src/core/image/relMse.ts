/**
 * Relative mean squared error of an image against its reference, as rendering papers report it:
 *
 *     relMSE = 1/M Σ (xᵢ − refᵢ)² / (refᵢ² + ε),   ε = 10⁻²,
 *
 * over the M values (pixels, or pixel channels) where both images are finite. Dividing by ref²
 * weighs an error by how visible it is against the local brightness; ε = 10⁻², the value the
 * Monte Carlo denoising literature uses, keeps near-black pixels from dominating the mean. Values
 * are linear (radiance, not 8-bit sRGB); {@link relMseRgba8} linearizes 8-bit images first.
 */
import { srgbToLinear } from './flip';

/** The ε of relMSE's denominator. */
export const REL_MSE_EPSILON = 1e-2;

/** relMSE of `test` against `reference` (equal lengths); NaN when no value pair is finite. */
export function relMse(
  test: ArrayLike<number>,
  reference: ArrayLike<number>,
  epsilon = REL_MSE_EPSILON,
): number {
  if (test.length !== reference.length)
    throw new RangeError(
      `relMSE needs images of one size: ${test.length} values against ${reference.length}`,
    );
  let sum = 0;
  let m = 0;
  for (let i = 0; i < test.length; i++) {
    const x = test[i];
    const r = reference[i];
    if (!Number.isFinite(x) || !Number.isFinite(r)) continue;
    const d = x - r;
    sum += (d * d) / (r * r + epsilon);
    m++;
  }
  return m ? sum / m : NaN;
}

/**
 * relMSE of two RGBA8 sRGB images of one size over their linear R, G, B values (each byte decoded
 * by the sRGB transfer function; alpha ignored): for images that exist only as shown pixels.
 */
export function relMseRgba8(
  test: ArrayLike<number>,
  reference: ArrayLike<number>,
  epsilon = REL_MSE_EPSILON,
): number {
  if (test.length !== reference.length)
    throw new RangeError(`relMSE needs images of one size: ${test.length} bytes against ${reference.length}`);
  const n = test.length >> 2;
  const x = new Float64Array(3 * n);
  const r = new Float64Array(3 * n);
  for (let i = 0; i < n; i++)
    for (let c = 0; c < 3; c++) {
      x[3 * i + c] = srgbToLinear(test[4 * i + c] / 255);
      r[3 * i + c] = srgbToLinear(reference[4 * i + c] / 255);
    }
  return relMse(x, r, epsilon);
}
