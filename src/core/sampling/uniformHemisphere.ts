/**
 * Uniform sampling of the upper hemisphere (z ≥ 0) with respect to solid angle: p(ω) = 1/(2π).
 *
 * Derivation: p(θ, φ) = sin θ /(2π); marginal p(θ) = sin θ, P(θ) = 1 − cos θ; with ξ₁ ↦ 1 − ξ₁
 * (same distribution) cos θ = ξ₁, φ = 2π ξ₂.
 * Source: pbrt-v4 section A.5.2, `SampleUniformHemisphere` / `UniformHemispherePDF` /
 * `InvertUniformHemisphereSample` (util/sampling.h).
 */
import type { VecOut } from './sphericalCoords';
import { INV_TWO_PI, TWO_PI, clampUnit, sphericalPhi, writeSphericalDirection } from './sphericalCoords';

/**
 * Sample a direction uniformly on the upper hemisphere (z-up).
 * Domain: u1, u2 ∈ [0, 1). Writes the unit vector (x, y, z), z = u1 ∈ [0, 1), into out[o..o+2].
 * Measure: solid angle, pdf {@link uniformHemispherePdf}. Source: pbrt-v4 A.5.2.
 * sin θ is computed as √((1 − z)(1 + z)), which keeps precision near the pole (z → 1).
 */
export function sampleUniformHemisphere(u1: number, u2: number, out: VecOut, o = 0): VecOut {
  const z = u1;
  const r = Math.sqrt(Math.max(0, (1 - z) * (1 + z)));
  return writeSphericalDirection(r, z, TWO_PI * u2, out, o);
}

/**
 * Density of {@link sampleUniformHemisphere} per unit solid angle at the unit direction (x, y, z):
 * 1/(2π) for z ≥ 0, 0 otherwise (and 0 for NaN). Only z (= cos θ) matters.
 */
export function uniformHemispherePdf(_x: number, _y: number, z: number): number {
  return z >= 0 ? INV_TWO_PI : 0;
}

/**
 * Inverse of {@link sampleUniformHemisphere}: the (u1, u2) ∈ [0, 1)² that maps to the unit direction
 * (x, y, z) with z ≥ 0. u1 = z, u2 = φ/(2π). Source: pbrt-v4 `InvertUniformHemisphereSample`.
 */
export function invertUniformHemisphereSample(x: number, y: number, z: number): [number, number] {
  return [clampUnit(z), clampUnit(sphericalPhi(x, y) * INV_TWO_PI)];
}

/**
 * Batched {@link sampleUniformHemisphere}: reads u[2i], u[2i+1] and writes out[3i..3i+2] for
 * i ∈ [start, n). Caller-owned buffers, no allocation.
 */
export function sampleUniformHemisphereBatch(
  u: Float64Array,
  out: Float64Array,
  n: number,
  start = 0,
): Float64Array {
  for (let i = start; i < n; i++) sampleUniformHemisphere(u[2 * i], u[2 * i + 1], out, 3 * i);
  return out;
}
