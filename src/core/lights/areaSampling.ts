/**
 * Uniform sampling of a rectangle by area, the strategy of the exam key's Q6(c):
 * x = s + ξ₁ w ex + ξ₂ h ey, with density p_A = 1/|A| per unit AREA. Converted to the solid-angle
 * measure at a shading point p (the change of variables of Q6(a)):
 * p_ω = p_A · r² / cos θ_l = r² / (|A| cos θ_l), r = |x − p|, cos θ_l = |n_l · (p − x)| / r.
 * Source: pbrt-v4 section 6.5.4 (`Shape::Sample` by area, `PDF` converted with
 * `DistanceSquared / AbsDot(n, -wi)`), and the exam key Q6(c).
 */
import type { RectLight } from './rectLight';

/**
 * A sampler of points on a rectangle light: for (u1, u2) ∈ [0, 1]² it writes the point (x, y, z)
 * into out[o..o+2] (o defaults to 0). `S` is what it samples from: the light itself (by area,
 * {@link sampleRectArea}) or the light seen from a point (by solid angle, sampleSphericalRectangle).
 */
export type RectPointSampler<S> = (
  from: S,
  u1: number,
  u2: number,
  out: Float64Array | number[],
  o?: number,
) => void;

/**
 * Uniform point on the rectangle (area measure). Domain: u1, u2 ∈ [0, 1]. Writes (x, y, z) into
 * out[o..o+2]. Pdf: {@link rectAreaPdf} (per unit area).
 */
export const sampleRectArea: RectPointSampler<RectLight> = (light, u1, u2, out, o = 0) => {
  const s = light.corner,
    a = light.edgeX,
    b = light.edgeY;
  out[o] = s[0] + u1 * a[0] + u2 * b[0];
  out[o + 1] = s[1] + u1 * a[1] + u2 * b[1];
  out[o + 2] = s[2] + u1 * a[2] + u2 * b[2];
};

/**
 * Density of {@link sampleRectArea} per unit AREA at the point x: 1/|A| on the rectangle; 0 off it
 * (off its plane or outside its edges by more than 1e-9 × max(1, w, h, |corner|)) and for a
 * degenerate rectangle. The estimators of areaLightEstimators.ts call it for every area sample.
 */
export function rectAreaPdf(light: RectLight, x: number, y: number, z: number): number {
  if (!(light.area > 0)) return 0;
  const sx = x - light.corner[0],
    sy = y - light.corner[1],
    sz = z - light.corner[2];
  // Relative to the rectangle's size AND its position: a sampled point far from the origin carries
  // an absolute rounding error of ~|corner|·2⁻⁵³ that must not push it "off" the rectangle.
  const s0 = light.corner;
  const tol =
    1e-9 * Math.max(1, light.width, light.height, Math.abs(s0[0]), Math.abs(s0[1]), Math.abs(s0[2]));
  const a = sx * light.ex[0] + sy * light.ex[1] + sz * light.ex[2];
  const b = sx * light.ey[0] + sy * light.ey[1] + sz * light.ey[2];
  const c = sx * light.normal[0] + sy * light.normal[1] + sz * light.normal[2];
  if (!(Math.abs(c) <= tol && a >= -tol && a <= light.width + tol && b >= -tol && b <= light.height + tol))
    return 0;
  return 1 / light.area;
}

/**
 * Convert an area density to a solid-angle density at the shading point p:
 * p_ω = p_A r² / |cos θ_l| (the inverse Jacobian of Q6(a)). Domain: pA ≥ 0, r² ≥ 0, cosThetaL any.
 * Returns 0 when cos θ_l = 0 (the light seen edge-on has no solid angle to spread the density over
 * — the pbrt convention of returning 0 rather than Infinity) or for non-finite input.
 * Source: pbrt-v4 section 4.2.3 eq. (4.9) and 6.5.4.
 */
export function areaToSolidAnglePdf(pA: number, r2: number, cosThetaL: number): number {
  const c = Math.abs(cosThetaL);
  if (!(c > 0) || !(pA >= 0) || !(r2 >= 0)) return 0;
  const v = (pA * r2) / c;
  return Number.isFinite(v) ? v : 0;
}
