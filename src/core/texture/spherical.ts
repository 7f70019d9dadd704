/**
 * Spherical texture coordinates of a point, as in the exam's Q3(c): the sphere is
 * x = r cos u sin v, y = r sin u sin v, z = r cos v (z-up, v the polar angle from +z, u the
 * azimuth from +x toward +y), so
 *
 *   u = atan2(y, x) ∈ [0, 2π),   v = arccos(z / r) ∈ [0, π],
 *
 * and the texture coordinates are their normalization (u / 2π, v / π) ∈ [0, 1) × [0, 1].
 *
 * Robustness:
 * - The seam: atan2 returns (−π, π]; negative angles get + 2π. When that sum rounds to exactly
 *   2π (atan2 of a tiny negative y), the angle is set to 0, so u is always in [0, 1): the seam
 *   φ = 0 belongs to u = 0, never to u = 1.
 * - The poles: where x = y = 0 (on the z axis) the azimuth is undefined; we define u = 0 there.
 *   (atan2(±0, −0) would otherwise give ±π depending on signed zeros.)
 * - v is computed as atan2(√(x² + y²), z), which equals arccos(z / r) but keeps full precision
 *   near the poles, where arccos has infinite slope and z / r loses the small angle to rounding.
 * - The point at the origin (r = 0), or any non-finite coordinate, has no direction: an error.
 *
 * Source: the exam's Q3(c); pbrt-v4 §3.8.3 (SphericalTheta / SphericalPhi, with the same
 * "add 2π to negative φ" rule and clamped arccos); Ray Tracing Gems ch. 6 on precision.
 */
import { TWO_PI } from '../sampling/sphericalCoords';
import { fail, type Failure } from '../failure';

/** The result of {@link sphericalUV}: both the angles (the "forgot to normalize" variant) and (u, v). */
export type SphericalUV =
  | {
      ok: true;
      /** Distance from the origin, r = √(x² + y² + z²). */
      r: number;
      /** Azimuth u = atan2(y, x) in radians, in [0, 2π). */
      phi: number;
      /** Polar angle v = arccos(z / r) in radians, in [0, π]. */
      theta: number;
      /** Normalized u = φ / 2π ∈ [0, 1). */
      u: number;
      /** Normalized v = θ / π ∈ [0, 1]. */
      v: number;
      /** True when x = y = 0 (a pole), where u is defined as 0. */
      pole: boolean;
    }
  | Failure<'nonfinite' | 'origin'>;

/**
 * Spherical (u, v) of the point (x, y, z) about the origin. Domain: finite, not all zero.
 * See the module comment for the seam and pole rules.
 */
export function sphericalUV(x: number, y: number, z: number): SphericalUV {
  if (!Number.isFinite(x) || !Number.isFinite(y) || !Number.isFinite(z)) {
    return fail('nonfinite', 'The sphere point has a coordinate that is not a finite number.');
  }
  const r = Math.hypot(x, y, z);
  if (r === 0) {
    return fail('origin', 'The point (0, 0, 0) is the sphere’s centre: it has no direction, so no (u, v).');
  }
  const rho = Math.hypot(x, y);
  const pole = x === 0 && y === 0;
  let phi = pole ? 0 : Math.atan2(y, x) + 0; // + 0 turns −0 into +0
  if (phi < 0) phi += TWO_PI;
  if (phi >= TWO_PI) phi = 0;
  const theta = Math.atan2(rho, z); // = arccos(z / r), precise near the poles
  let u = phi / TWO_PI;
  if (u >= 1) u = 0;
  return { ok: true, r, phi, theta, u, v: theta / Math.PI, pole };
}

/**
 * The point on the sphere of radius r at normalized (u, v) (inverse of {@link sphericalUV} for
 * r > 0, u ∈ [0, 1), v ∈ [0, 1]): φ = 2π u, θ = π v, (r cos φ sin θ, r sin φ sin θ, r cos θ).
 */
export function spherePoint(u: number, v: number, r = 1): [number, number, number] {
  const phi = TWO_PI * u;
  const theta = Math.PI * v;
  const s = Math.sin(theta);
  return [r * Math.cos(phi) * s, r * Math.sin(phi) * s, r * Math.cos(theta)];
}
