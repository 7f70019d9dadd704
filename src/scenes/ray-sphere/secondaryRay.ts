/** Why renderers test t > t_min instead of t ≥ 0: a secondary ray that starts on the surface. */
import { intersectRaySphere, type RaySphereHit, type RaySphereMethod } from '../../core/geometry';
import { norm, scale, sub, type Vec3 } from '../../core/vec3';
import type { InputCheck } from './inputs';

export interface SecondaryRay {
  /** The starting point, computed in doubles (so not exactly on the sphere). */
  p: Vec3;
  /** |p − C| − r: how far rounding has put p off the surface. */
  offSurface: number;
  /** The outward normal at p: the ray's direction (a light straight above the surface). */
  n: Vec3;
  /** The secondary ray's intersection with the same sphere. */
  res: RaySphereHit;
  /** The root a t ≥ 0 test accepts (the surface hitting itself), or null. */
  selfHit: number | null;
  /** The root a t > t_min test accepts, or null. */
  hitWithTMin: number | null;
}

/** A renderer's t_min for this sphere: 10⁻⁴ r (scaled to the scene; t is a length along a unit direction here). */
export const tMinFor = (r: number) => 1e-4 * r;

/** The secondary ray leaving the point q (on the sphere up to rounding) along the outward normal. */
export function secondaryRay(q: Vec3, c: Vec3, r: number, method: RaySphereMethod): SecondaryRay | null {
  const f = sub(q, c);
  const len = norm(f);
  if (!(len > 0) || !Number.isFinite(len)) return null;
  const n = scale(f, 1 / len);
  const res = intersectRaySphere(q, n, c, r, method);
  if (!res.ok) return null;
  const tMin = tMinFor(r);
  const roots = res.t0 === null ? [] : [res.t0, res.t1!];
  const after = roots.filter((t) => t > tMin);
  return {
    p: q,
    offSurface: len - r,
    n,
    res,
    selfHit: res.tHit,
    hitWithTMin: after.length ? Math.min(...after) : null,
  };
}

/** The secondary ray from the current ray's hit point p = o + t_hit d, or null without a hit. */
export function secondaryFromHit(
  input: InputCheck,
  hit: RaySphereHit | null,
  method: RaySphereMethod,
): SecondaryRay | null {
  if (!hit || hit.tHit === null) return null;
  const { o, d, c, r } = input;
  const t = hit.tHit;
  return secondaryRay([o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]], c, r, method);
}

/**
 * Secondary rays from `count` points spread evenly over the sphere (a Fibonacci lattice), each
 * point computed in doubles as C + r n: how many see their own surface with t ≥ 0, and with
 * t > t_min. Deterministic.
 */
export function selfIntersectionSurvey(
  c: Vec3,
  r: number,
  method: RaySphereMethod,
  count = 1000,
): SurveyCounts {
  return selfIntersectionSurveyRange(c, r, method, count, 0, count);
}

export interface SurveyCounts {
  /** Points whose secondary ray could be cast. */
  count: number;
  /** Of those, rays that hit their own surface with t ≥ 0, and with t > t_min. */
  withZero: number;
  withTMin: number;
}

/**
 * The survey's points k0 … k1 − 1 of `count` only (the counts of consecutive ranges add up to the
 * whole survey's): lets a page cast the rays in short tasks.
 */
export function selfIntersectionSurveyRange(
  c: Vec3,
  r: number,
  method: RaySphereMethod,
  count: number,
  k0: number,
  k1: number,
): SurveyCounts {
  const golden = Math.PI * (3 - Math.sqrt(5));
  let withZero = 0;
  let withTMin = 0;
  let n = 0;
  for (let k = Math.max(0, k0); k < Math.min(count, k1); k++) {
    const z = 1 - (2 * (k + 0.5)) / count;
    const s = Math.sqrt(Math.max(0, 1 - z * z));
    const ph = k * golden;
    const u: Vec3 = [s * Math.cos(ph), s * Math.sin(ph), z];
    const sec = secondaryRay([c[0] + r * u[0], c[1] + r * u[1], c[2] + r * u[2]], c, r, method);
    if (!sec) continue;
    n++;
    if (sec.selfHit !== null) withZero++;
    if (sec.hitWithTMin !== null) withTMin++;
  }
  return { count: n, withZero, withTMin };
}
