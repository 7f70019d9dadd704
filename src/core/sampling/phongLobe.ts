/**
 * Normalized Phong lobe around +z: p(ω) = (n + 1)/(2π) cosⁿθ per unit solid angle on the upper
 * hemisphere, exponent n ≥ 0 (n = 0 is the uniform hemisphere, n = 1 the cosine lobe).
 *
 * Derivation: p(θ, φ) = (n+1)/(2π) cosⁿθ sin θ; p(θ) = (n+1) cosⁿθ sin θ, P(θ) = 1 − cos^{n+1}θ;
 * using 1 − ξ₁ in place of ξ₁ (same distribution), cos θ = ξ₁^{1/(n+1)}, φ = 2π ξ₂.
 * Computed in log space: ln cos θ = ln ξ₁/(n+1), sin θ = √(−expm1(2 ln ξ₁/(n+1))), which stays
 * accurate for large n and ξ₁ near 1 (where 1 − cos²θ would cancel).
 * Source: Lafortune & Willems 1994, "Using the modified Phong reflectance model for physically
 * based rendering"; pbrt-v4 section 2.3 (inversion); Walter et al. 2007 for the sin θ form idea.
 */
import type { VecOut } from './sphericalCoords';
import { INV_TWO_PI, TWO_PI, clampUnit, sphericalPhi, writeSphericalDirection } from './sphericalCoords';

/**
 * Sample the Phong lobe cosⁿθ. Domain: u1, u2 ∈ [0, 1), exponent n ≥ 0 (finite; negative or NaN
 * treated as 0). Writes the unit vector into out[o..o+2]. Measure: solid angle; pdf
 * {@link phongLobePdf}.
 */
export function samplePhongLobe(u1: number, u2: number, exponent: number, out: VecOut, o = 0): VecOut {
  const inv = 1 / ((exponent > 0 ? exponent : 0) + 1);
  const lc = Math.log(u1) * inv; // ln cos θ (−∞ at u1 = 0: cos θ = 0, horizon)
  const c = Math.exp(lc);
  const s = Math.sqrt(Math.max(0, -Math.expm1(2 * lc)));
  return writeSphericalDirection(s, c, TWO_PI * u2, out, o);
}

/**
 * Density of {@link samplePhongLobe} per unit solid angle at the unit direction (x, y, z):
 * (n+1)/(2π) cosⁿθ with cos θ = z for z ≥ 0, 0 below the horizon and for NaN. Exponent n ≥ 0.
 */
export function phongLobePdf(_x: number, _y: number, cosTheta: number, exponent: number): number {
  if (!(cosTheta >= 0)) return 0;
  const n = exponent > 0 ? exponent : 0;
  return (n + 1) * INV_TWO_PI * Math.pow(cosTheta, n);
}

/**
 * Inverse of {@link samplePhongLobe}: u1 = cos^{n+1}θ, u2 = φ/(2π) for the direction (x, y, z),
 * z ≥ 0 (normalized internally).
 */
export function invertPhongLobeSample(x: number, y: number, z: number, exponent: number): [number, number] {
  const n = exponent > 0 ? exponent : 0;
  const len = Math.hypot(x, y, z);
  const c = len > 0 ? z / len : 0;
  const u1 = c > 0 ? Math.exp((n + 1) * Math.log(c)) : 0;
  return [clampUnit(u1), clampUnit(sphericalPhi(x, y) * INV_TWO_PI)];
}

/** Marginal density of θ: (n+1) cosⁿθ sin θ on [0, π/2], 0 elsewhere (per unit θ). */
export function phongThetaPdf(theta: number, exponent: number): number {
  if (!(theta >= 0 && theta <= Math.PI / 2)) return 0;
  const n = exponent > 0 ? exponent : 0;
  return (n + 1) * Math.pow(Math.cos(theta), n) * Math.sin(theta);
}

/** Marginal CDF of θ: 1 − cos^{n+1}θ, clamped to [0, 1]. */
export function phongThetaCdf(theta: number, exponent: number): number {
  if (!(theta > 0)) return 0;
  if (theta >= Math.PI / 2) return 1;
  const n = exponent > 0 ? exponent : 0;
  return -Math.expm1((n + 1) * Math.log(Math.cos(theta)));
}

/**
 * Batched {@link samplePhongLobe}: reads u[2i], u[2i+1], writes out[3i..3i+2], i ∈ [start, n).
 * Same order as the scalar sampler: inputs, the exponent, then the output.
 */
export function samplePhongLobeBatch(
  u: Float64Array,
  exponent: number,
  out: Float64Array,
  n: number,
  start = 0,
): Float64Array {
  for (let i = start; i < n; i++) samplePhongLobe(u[2 * i], u[2 * i + 1], exponent, out, 3 * i);
  return out;
}
