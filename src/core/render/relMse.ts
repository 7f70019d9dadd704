/**
 * Relative mean squared error of an image against a reference, the error measure of rendering
 * papers (e.g. Rousselle et al. 2011; Müller et al. 2017):
 *
 *     relMSE = (1/N) Σ_k (I_k − R_k)² / (R_k² + ε),
 *
 * ε (default 10⁻²) keeping black reference pixels from dividing by zero. Pixels whose reference is
 * not finite are skipped (and not counted).
 */
export const REL_MSE_EPSILON = 1e-2;

export function relMse(
  image: ArrayLike<number>,
  reference: ArrayLike<number>,
  epsilon = REL_MSE_EPSILON,
): number {
  let sum = 0;
  let n = 0;
  for (let k = 0; k < reference.length; k++) {
    const r = reference[k];
    if (!Number.isFinite(r)) continue;
    const e = image[k] - r;
    sum += (e * e) / (r * r + epsilon);
    n++;
  }
  return n > 0 ? sum / n : NaN;
}
