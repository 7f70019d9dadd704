/**
 * A one-sided rectangular emitter: centre c, size w × h, tilted by `tilt` degrees about its own
 * x axis. At tilt 0 the rectangle is horizontal and emits downwards (normal −z), the exam's
 * ceiling light over a floor. World space is z-up.
 *
 * Frame: ex = (1, 0, 0), ey = (0, cos t, sin t) (ey rotated about x by t), and the emitting normal
 * n_l = ey × ex = (0, sin t, −cos t). Corners in counter-clockwise order around ex × ey:
 * s = c − (w/2) ex − (h/2) ey, s + w ex, s + w ex + h ey, s + h ey (pbrt's "s, ex, ey" convention,
 * pbrt-v4 section 6.5.4 / `SampleSphericalRectangle`).
 */
import { parallelogramSolidAngle } from '../geometry/solidAngle';

import type { Vec3 } from '../vec3';

export type { Vec3 };

/** A rectangle in space: the emitter (or an occluder). All vectors world space, z-up. */
export interface RectLight {
  /** Centre c. */
  center: Vec3;
  /** Full width w along ex and height h along ey (≥ 0). */
  width: number;
  height: number;
  /** Tilt about the rectangle's own x axis, degrees (0 faces −z). */
  tiltDeg: number;
  /** Unit edge directions. */
  ex: Vec3;
  ey: Vec3;
  /** Unit emitting normal n_l (the side that emits; the back is black). */
  normal: Vec3;
  /** The corner s = c − (w/2) ex − (h/2) ey. */
  corner: Vec3;
  /** Full edge vectors w·ex and h·ey. */
  edgeX: Vec3;
  edgeY: Vec3;
  /** The four corners, counter-clockwise about ex × ey: s, s + w ex, s + w ex + h ey, s + h ey. */
  corners: [Vec3, Vec3, Vec3, Vec3];
  /** Area |A| = w h. */
  area: number;
}

/**
 * sin and cos of an angle in degrees, exact at multiples of 90° (so tilt 180 faces exactly +z).
 * Domain: any finite degrees. Returns [sin, cos].
 */
export function sinCosDeg(deg: number): [number, number] {
  const r = ((deg % 360) + 360) % 360;
  if (r === 0) return [0, 1];
  if (r === 90) return [1, 0];
  if (r === 180) return [0, -1];
  if (r === 270) return [-1, 0];
  const a = (r * Math.PI) / 180;
  return [Math.sin(a), Math.cos(a)];
}

/**
 * Build a rectangle from its centre, size and tilt (see file comment for the frame).
 * Domain: finite centre; width, height ≥ 0 (negative or non-finite sizes are taken as 0, which
 * gives a degenerate light of area 0 that every routine treats as emitting nothing); finite tilt.
 */
export function makeRectLight(
  center: readonly number[],
  width: number,
  height: number,
  tiltDeg = 0,
): RectLight {
  const w = Number.isFinite(width) && width > 0 ? width : 0;
  const h = Number.isFinite(height) && height > 0 ? height : 0;
  const t = Number.isFinite(tiltDeg) ? tiltDeg : 0;
  const [s, c] = sinCosDeg(t);
  const ex: Vec3 = [1, 0, 0];
  const ey: Vec3 = [0, c, s];
  const normal: Vec3 = [0, s, 0 - c]; // 0 − c: +0 rather than −0 at tilt ±90°
  const cx = center[0],
    cy = center[1],
    cz = center[2];
  const corner: Vec3 = [
    cx - (w / 2) * ex[0] - (h / 2) * ey[0],
    cy - (w / 2) * ex[1] - (h / 2) * ey[1],
    cz - (w / 2) * ex[2] - (h / 2) * ey[2],
  ];
  const edgeX: Vec3 = [w * ex[0], w * ex[1], w * ex[2]];
  const edgeY: Vec3 = [h * ey[0], h * ey[1], h * ey[2]];
  const corners: [Vec3, Vec3, Vec3, Vec3] = [
    [corner[0], corner[1], corner[2]],
    [corner[0] + edgeX[0], corner[1] + edgeX[1], corner[2] + edgeX[2]],
    [corner[0] + edgeX[0] + edgeY[0], corner[1] + edgeX[1] + edgeY[1], corner[2] + edgeX[2] + edgeY[2]],
    [corner[0] + edgeY[0], corner[1] + edgeY[1], corner[2] + edgeY[2]],
  ];
  return {
    center: [cx, cy, cz],
    width: w,
    height: h,
    tiltDeg: t,
    ex,
    ey,
    normal,
    corner,
    edgeX,
    edgeY,
    corners,
    area: w * h,
  };
}

/**
 * Signed distance of point p from the rectangle's plane along its emitting normal: > 0 in front
 * (lit side), < 0 behind, 0 on the plane. Domain: finite p.
 */
export function rectPlaneDistance(light: RectLight, px: number, py: number, pz: number): number {
  const n = light.normal;
  return (px - light.center[0]) * n[0] + (py - light.center[1]) * n[1] + (pz - light.center[2]) * n[2];
}

/**
 * True when the point p sees the emitting side
 * (signed plane distance > 0) and the light has positive area.
 */
export function rectFacesPoint(light: RectLight, px: number, py: number, pz: number): boolean {
  return light.area > 0 && rectPlaneDistance(light, px, py, pz) > 0;
}

/**
 * Ray–rectangle intersection: the parameter t > tMin of the hit of o + t d with the rectangle
 * (either side), or Infinity on a miss (parallel ray, behind the origin, outside the edges,
 * degenerate rectangle). The edges are inclusive. Domain: finite o, d (d need not be unit; t is
 * in units of d). Source: plane intersection + local coordinates (pbrt-v4 section 6.5 for the
 * bilinear-patch special case of a rectangle).
 */
export function intersectRect(
  light: RectLight,
  ox: number,
  oy: number,
  oz: number,
  dx: number,
  dy: number,
  dz: number,
  tMin = 0,
): number {
  if (!(light.area > 0)) return Infinity;
  const n = light.normal;
  const dn = dx * n[0] + dy * n[1] + dz * n[2];
  if (dn === 0 || !Number.isFinite(dn)) return Infinity;
  const s = light.corner;
  const t = ((s[0] - ox) * n[0] + (s[1] - oy) * n[1] + (s[2] - oz) * n[2]) / dn;
  if (!(t > tMin) || !Number.isFinite(t)) return Infinity;
  const hx = ox + t * dx - s[0];
  const hy = oy + t * dy - s[1];
  const hz = oz + t * dz - s[2];
  const a = hx * light.ex[0] + hy * light.ex[1] + hz * light.ex[2];
  const b = hx * light.ey[0] + hy * light.ey[1] + hz * light.ey[2];
  if (a < 0 || a > light.width || b < 0 || b > light.height) return Infinity;
  return t;
}

/**
 * Solid angle of the rectangle seen from p (steradians, [0, 2π]), by Van Oosterom–Strackee over two
 * triangles with exact edge vectors (robust for tiny and distant lights). 0 for a degenerate
 * rectangle or p in its plane. Seen from either side (the geometric solid angle; whether the light
 * emits towards p is {@link rectFacesPoint}).
 */
export function rectSolidAngle(light: RectLight, px: number, py: number, pz: number): number {
  if (!(light.area > 0)) return 0;
  const s = light.corner;
  return parallelogramSolidAngle(
    s[0] - px,
    s[1] - py,
    s[2] - pz,
    light.edgeX[0],
    light.edgeX[1],
    light.edgeX[2],
    light.edgeY[0],
    light.edgeY[1],
    light.edgeY[2],
  );
}
