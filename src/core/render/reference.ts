/**
 * The reference value of the radiance leaving a shading point towards the eye, exact where a
 * closed form exists:
 *
 * - on a Lambertian surface with bounces = 1 (direct light only) and every light unoccluded from
 *   the point, L_o = (ρ/π) Σ_k L_k ∫_{light k} max(0, cos θ) dω, the integral by Lambert's polygon
 *   formula (Lambert 1760; Arvo 1995; core/lights/polygonIrradiance, with the horizon clip);
 * - on the furnace's sphere, alone in a uniform environment L_env, at any bounce count:
 *   L_o = ρ L_env (a convex object never sees itself, so every path escapes after one bounce and
 *   ∫ L_env cos θ dω = π L_env).
 *
 * A light is unoccluded when nothing in the scene can cut the pyramid with apex p and the light as
 * its base: the floor (when p is on the sphere, every corner of the light must be above the floor
 * and p not below it), the sphere (when p is not on it, the sphere must lie at least r outside one
 * face plane of the pyramid: a sufficient test, so a sphere grazing the pyramid from outside makes
 * the reference "converged", never a wrong "exact"), and no plates or other lights at all.
 */
import { rectProjectedSolidAngle } from '../lights/polygonIrradiance';
import type { RectLight } from '../lights/rectLight';
import type { Vertex } from './material';
import type { HitKind } from './intersect';
import type { RenderScene } from './scene';

/** True when the sphere (centre c, radius r) lies wholly outside one face plane of the pyramid (p; light). */
export function sphereClearOfPyramid(
  light: RectLight,
  px: number,
  py: number,
  pz: number,
  c: readonly number[],
  r: number,
): boolean {
  const cs = light.corners;
  // centroid of the base, to orient each side plane outwards
  const gx = light.center[0] - px,
    gy = light.center[1] - py,
    gz = light.center[2] - pz;
  const cx = c[0] - px,
    cy = c[1] - py,
    cz = c[2] - pz;
  for (let i = 0; i < 4; i++) {
    const a = cs[i],
      b = cs[(i + 1) % 4];
    const ax = a[0] - px,
      ay = a[1] - py,
      az = a[2] - pz;
    const bx = b[0] - px,
      by = b[1] - py,
      bz = b[2] - pz;
    let mx = ay * bz - az * by,
      my = az * bx - ax * bz,
      mz = ax * by - ay * bx;
    const ml = Math.hypot(mx, my, mz);
    if (!(ml > 0)) continue;
    if (mx * gx + my * gy + mz * gz > 0) {
      mx = -mx;
      my = -my;
      mz = -mz;
    }
    if ((mx * cx + my * cy + mz * cz) / ml >= r) return true;
  }
  // beyond the light's plane, on the side away from p
  const n = light.normal;
  const beyond = -(
    (c[0] - light.center[0]) * n[0] +
    (c[1] - light.center[1]) * n[1] +
    (c[2] - light.center[2]) * n[2]
  );
  return beyond >= r;
}

/**
 * The exact radiance leaving the vertex v (on a surface of kind `on`) towards the eye under the
 * rules of the module comment, or null where no closed form applies.
 */
export function exactRadiance(scene: RenderScene, v: Vertex, on: HitKind, bounces: number): number | null {
  if (v.glossy || (on !== 'floor' && on !== 'sphere')) return null;
  const s = scene.sphere;
  if (scene.environment > 0) {
    const alone =
      on === 'sphere' && scene.lights.length === 0 && scene.plates.length === 0 && scene.floorAlbedo === null;
    return alone ? v.albedo * scene.environment : null;
  }
  if (bounces !== 1 || scene.plates.length > 0 || scene.lights.length !== 1) return null;
  const { rect, L } = scene.lights[0];
  if (on === 'sphere') {
    if (scene.floorAlbedo !== null && (v.pz < 0 || rect.corners.some((k) => !(k[2] > 0)))) return null;
  } else if (s && !sphereClearOfPyramid(rect, v.px, v.py, v.pz, s.center, s.radius)) {
    return null;
  }
  return (v.albedo / Math.PI) * L * rectProjectedSolidAngle(rect, v.px, v.py, v.pz, v.nx, v.ny, v.nz);
}
