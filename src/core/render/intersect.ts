/**
 * The closest hit of a ray among the scene's objects: the floor z = 0, the sphere (by the stable
 * quadratic of core/geometry/raySphere, Ray Tracing Gems ch. 7), the lights and the plates
 * (core/lights/rectLight `intersectRect`). Rays are o + t d with t ≥ 0 in units of d; callers
 * start secondary rays a little off the surface ({@link offsetOrigin}) rather than asking for
 * t > ε, so a grazing ray is not lost.
 */
import { intersectRaySphere } from '../geometry/raySphere';
import { intersectRect } from '../lights/rectLight';
import type { RenderScene } from './scene';

/** What a ray hits; `plate` only in the veach scene. */
export type HitKind = 'none' | 'floor' | 'sphere' | 'light' | 'plate';

/** The closest hit, filled in place: the object, t, the point and the geometric unit normal. */
export interface Hit {
  kind: HitKind;
  /** Which light or plate (0 otherwise). */
  index: number;
  t: number;
  px: number;
  py: number;
  pz: number;
  /** The object's outward normal (the floor's +z, the sphere's radial, a rectangle's front). */
  nx: number;
  ny: number;
  nz: number;
}

export function newHit(): Hit {
  return { kind: 'none', index: 0, t: Infinity, px: 0, py: 0, pz: 0, nx: 0, ny: 0, nz: 1 };
}

/**
 * Fill `hit` with the closest intersection of o + t d (0 ≤ t < tMax) and return its kind
 * ('none' when nothing is hit before tMax). Domain: finite o, d ≠ 0.
 */
export function closestHit(
  scene: RenderScene,
  ox: number,
  oy: number,
  oz: number,
  dx: number,
  dy: number,
  dz: number,
  tMax: number,
  hit: Hit,
): HitKind {
  let best = tMax;
  let kind: HitKind = 'none';
  let index = 0;
  if (scene.floorAlbedo !== null && dz !== 0) {
    const t = -oz / dz;
    if (t >= 0 && t < best) {
      best = t;
      kind = 'floor';
    }
  }
  const s = scene.sphere;
  if (s) {
    const r = intersectRaySphere([ox, oy, oz], [dx, dy, dz], s.center, s.radius);
    if (r.ok && r.tHit !== null && r.tHit < best) {
      best = r.tHit;
      kind = 'sphere';
    }
  }
  for (let k = 0; k < scene.lights.length; k++) {
    const t = intersectRect(scene.lights[k].rect, ox, oy, oz, dx, dy, dz, 0);
    if (t < best) {
      best = t;
      kind = 'light';
      index = k;
    }
  }
  for (let k = 0; k < scene.plates.length; k++) {
    const t = intersectRect(scene.plates[k].rect, ox, oy, oz, dx, dy, dz, 0);
    if (t < best) {
      best = t;
      kind = 'plate';
      index = k;
    }
  }
  hit.kind = kind;
  hit.index = index;
  hit.t = kind === 'none' ? Infinity : best;
  if (kind === 'none') return kind;
  const px = ox + best * dx,
    py = oy + best * dy,
    pz = oz + best * dz;
  hit.px = px;
  hit.py = py;
  hit.pz = kind === 'floor' ? 0 : pz;
  if (kind === 'floor') {
    hit.nx = 0;
    hit.ny = 0;
    hit.nz = 1;
  } else if (kind === 'sphere' && s) {
    hit.nx = (px - s.center[0]) / s.radius;
    hit.ny = (py - s.center[1]) / s.radius;
    hit.nz = (pz - s.center[2]) / s.radius;
    const l = Math.hypot(hit.nx, hit.ny, hit.nz);
    hit.nx /= l;
    hit.ny /= l;
    hit.nz /= l;
  } else {
    const n = kind === 'light' ? scene.lights[index].rect.normal : scene.plates[index].rect.normal;
    hit.nx = n[0];
    hit.ny = n[1];
    hit.nz = n[2];
  }
  return kind;
}

/** How far off a surface secondary rays start, relative to the scale of the point's coordinates. */
export const RAY_OFFSET = 1e-9;

/**
 * The origin of a ray leaving the point p on the side of the unit normal n: p + ε n with
 * ε = 10⁻⁹ · max(1, |p|∞), written into out[0..2].
 */
export function offsetOrigin(
  px: number,
  py: number,
  pz: number,
  nx: number,
  ny: number,
  nz: number,
  out: Float64Array | number[],
): void {
  const e = RAY_OFFSET * Math.max(1, Math.abs(px), Math.abs(py), Math.abs(pz));
  out[0] = px + e * nx;
  out[1] = py + e * ny;
  out[2] = pz + e * nz;
}
