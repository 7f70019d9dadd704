/**
 * Cosine-weighted sampling of the upper hemisphere (z ≥ 0): p(ω) = cos θ / π per unit solid angle.
 *
 * Malley's method: sample the unit disk uniformly (by area) and project up, z = √(1 − x² − y²).
 * The disk is sampled with Shirley & Chiu's concentric map (J. Graphics Tools 2(3), 1997), which
 * keeps strata compact and is invertible, so the warped grid the scene draws stays well shaped.
 * Source: pbrt-v4 section A.5.3, `SampleCosineHemisphere`, `CosineHemispherePDF`,
 * `InvertCosineHemisphereSample`, and A.5.1 `SampleUniformDiskConcentric` /
 * `InvertUniformDiskConcentricSample` (util/sampling.h).
 */
import { clampUnit, type VecOut } from './sphericalCoords';

const PI_OVER_4 = Math.PI / 4;
const PI_OVER_2 = Math.PI / 2;
const INV_PI = 1 / Math.PI;

/**
 * Concentric map of the square [0, 1)² onto the unit disk (area-preserving up to a constant):
 * writes (x, y) into out[o], out[o+1]. Domain u1, u2 ∈ [0, 1). Measure: area, density 1/π on the disk.
 * Source: Shirley & Chiu 1997; pbrt-v4 `SampleUniformDiskConcentric`.
 */
export function sampleUniformDiskConcentric(u1: number, u2: number, out: VecOut, o = 0): VecOut {
  const ox = 2 * u1 - 1;
  const oy = 2 * u2 - 1;
  if (ox === 0 && oy === 0) {
    out[o] = 0;
    out[o + 1] = 0;
    return out;
  }
  let r: number;
  let theta: number;
  if (Math.abs(ox) > Math.abs(oy)) {
    r = ox;
    theta = PI_OVER_4 * (oy / ox);
  } else {
    r = oy;
    theta = PI_OVER_2 - PI_OVER_4 * (ox / oy);
  }
  out[o] = r * Math.cos(theta);
  out[o + 1] = r * Math.sin(theta);
  return out;
}

/**
 * Inverse of {@link sampleUniformDiskConcentric}: the (u1, u2) ∈ [0, 1)² mapping to the disk point
 * (x, y), x² + y² ≤ 1. Source: pbrt-v4 `InvertUniformDiskConcentricSample`.
 */
export function invertUniformDiskConcentricSample(x: number, y: number): [number, number] {
  const theta = Math.atan2(y, x); // (−π, π]
  let r = Math.hypot(x, y);
  let ux: number;
  let uy: number;
  const at = Math.abs(theta);
  if (at < PI_OVER_4 || at > 3 * PI_OVER_4) {
    ux = r = x < 0 ? -r : r;
    if (x < 0) uy = ((y < 0 ? Math.PI + theta : theta - Math.PI) * r) / PI_OVER_4;
    else uy = (theta * r) / PI_OVER_4;
  } else {
    uy = r = y < 0 ? -r : r;
    if (y < 0) ux = (-(PI_OVER_2 + theta) * r) / PI_OVER_4;
    else ux = ((PI_OVER_2 - theta) * r) / PI_OVER_4;
  }
  return [clampUnit((ux + 1) / 2), clampUnit((uy + 1) / 2)];
}

/**
 * Sample a direction on the upper hemisphere (z-up) with density cos θ / π per unit solid angle.
 * Domain: u1, u2 ∈ [0, 1). Writes the unit vector (x, y, z), z ≥ 0, into out[o..o+2].
 * Pdf: {@link cosineHemispherePdf}. Source: pbrt-v4 A.5.3 (Malley's method, concentric disk).
 */
export function sampleCosineHemisphere(u1: number, u2: number, out: VecOut, o = 0): VecOut {
  sampleUniformDiskConcentric(u1, u2, out, o);
  const x = out[o];
  const y = out[o + 1];
  // 1 − x² − y² loses digits near the rim; (1 − r)(1 + r) keeps them.
  const r = Math.hypot(x, y);
  out[o + 2] = Math.sqrt(Math.max(0, (1 - r) * (1 + r)));
  return out;
}

/**
 * Density of {@link sampleCosineHemisphere} per unit solid angle at the unit direction (x, y, z):
 * cos θ / π = z/π for z > 0, else 0 (NaN → 0). Only z (= cos θ) matters.
 */
export function cosineHemispherePdf(_x: number, _y: number, z: number): number {
  return z > 0 ? z * INV_PI : 0;
}

/**
 * Inverse of {@link sampleCosineHemisphere}: the (u1, u2) ∈ [0, 1)² mapping to the unit direction
 * (x, y, z), z ≥ 0 (z is not needed: the disk point is (x, y)). Source: pbrt-v4
 * `InvertCosineHemisphereSample`.
 */
export function invertCosineHemisphereSample(x: number, y: number, _z?: number): [number, number] {
  void _z;
  return invertUniformDiskConcentricSample(x, y);
}

/**
 * Batched {@link sampleCosineHemisphere}: reads u[2i], u[2i+1], writes out[3i..3i+2] for
 * i ∈ [start, n). Caller-owned buffers, no allocation per sample. Written out like
 * sampleUniformHemisphereBatch rather than made by one factory taking the sampler: closures made
 * by one function share their type feedback in V8, so the inner call turns polymorphic, and the
 * batches ran 15–25 % slower per direction (interleaved, bundled, Node 20).
 */
export function sampleCosineHemisphereBatch(
  u: Float64Array,
  out: Float64Array,
  n: number,
  start = 0,
): Float64Array {
  for (let i = start; i < n; i++) sampleCosineHemisphere(u[2 * i], u[2 * i + 1], out, 3 * i);
  return out;
}
