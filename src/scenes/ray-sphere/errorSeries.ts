/**
 * The error of both methods against the sphere's distance: medians over fixed rays, against the
 * double-double reference, in a given arithmetic (float64 here, float32 in ./precisionF32).
 */
import {
  intersectRaySphere,
  raySphereReference,
  relativeError,
  type RaySphereMethod,
  type RaySphereResult,
} from '../../core/geometry';
import { add, scale, sub, type Vec3 } from '../../core/vec3';
import { distantSetup } from './distantImage';
import { relDisc } from './methodRow';

export interface ErrorSeries {
  /** |o − c| / r for each point. */
  dist: number[];
  /** Median relative error of Δ (vs the double-double reference), per method. */
  discNaive: number[];
  discStable: number[];
  /** Median relative error of t-hit (lost hits count as 1), per method. */
  hitNaive: number[];
  hitStable: number[];
}

/** Floor for plotting errors on a log axis (exact results plot at u = 2⁻⁵³ "or better"). */
export const ERROR_FLOOR = 2 ** -53;

/** The median of xs (the mean of the middle two for an even count); xs is not reordered. */
export function median(xs: number[]): number {
  const s = [...xs].sort((x, y) => x - y);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : 0.5 * (s[m - 1] + s[m]);
}

/** The rays of the error-against-distance plots at one distance, from the distant image's eye. */
export interface ErrorRays {
  eye: Vec3;
  dirs: Vec3[];
  centre: Vec3;
  r: number;
}

/**
 * The rays of the error-against-distance plots at distance D (in radii): from the distant image's
 * eye, aimed at 12 points 0.1 … 0.95 r off the sphere's centre (six offsets, two angles).
 */
export function errorRaysAt(D: number): ErrorRays {
  const s = distantSetup(D);
  const dirs: Vec3[] = [];
  for (const rho of [0.1, 0.3, 0.5, 0.7, 0.85, 0.95]) {
    for (const ang of [0.3, 2.1]) {
      const off = add(scale(s.right, Math.cos(ang)), scale(s.up, Math.sin(ang)));
      const aim = add(s.centre, scale(off, rho));
      dirs.push(sub(aim, s.eye));
    }
  }
  return { eye: s.eye, dirs, centre: s.centre, r: s.r };
}

/** The arithmetic an error series measures: what it makes of the inputs, its intersection, its floor. */
export interface ErrorArithmetic {
  /** The inputs as this arithmetic holds them (the reference is of these, so only the arithmetic counts). */
  round: (v: Vec3) => Vec3;
  intersect: (o: Vec3, d: Vec3, c: Vec3, r: number, method: RaySphereMethod) => RaySphereResult;
  /** Plotting floor on a log axis: exact results plot here. */
  floor: number;
}

/**
 * The median errors of both methods at each distance, in the given arithmetic, against the
 * double-double reference of the inputs as that arithmetic holds them. A distance where a method
 * has no ray to measure is left out. Deterministic.
 */
export function medianErrorSeries(
  distances: number[],
  arithmetic: ErrorArithmetic,
  raysAt: (D: number) => ErrorRays = errorRaysAt,
): ErrorSeries {
  const { round, intersect, floor } = arithmetic;
  const out: ErrorSeries = { dist: [], discNaive: [], discStable: [], hitNaive: [], hitStable: [] };
  for (const D of distances) {
    const s = raysAt(D);
    const eye = round(s.eye);
    const centre = round(s.centre);
    const errs: Record<RaySphereMethod, { disc: number[]; hit: number[] }> = {
      naive: { disc: [], hit: [] },
      stable: { disc: [], hit: [] },
    };
    for (const dir of s.dirs) {
      const d = round(dir);
      const ref = raySphereReference(eye, d, centre, s.r);
      if (!ref.ok) continue;
      for (const method of ['naive', 'stable'] as const) {
        const res = intersect(eye, d, centre, s.r, method);
        if (!res.ok) continue;
        errs[method].disc.push(Math.min(1, relDisc(res.discriminant, ref.discriminant)));
        errs[method].hit.push(Math.min(1, relativeError(res.tHit, ref.tHit) ?? 0));
      }
    }
    if (!errs.naive.disc.length || !errs.stable.disc.length) continue;
    out.dist.push(D);
    out.discNaive.push(Math.max(floor, median(errs.naive.disc)));
    out.discStable.push(Math.max(floor, median(errs.stable.disc)));
    out.hitNaive.push(Math.max(floor, median(errs.naive.hit)));
    out.hitStable.push(Math.max(floor, median(errs.stable.hit)));
  }
  return out;
}

/**
 * The error of each method in float64 against distance: for each distance D = 10^e (in radii),
 * the 12 rays of {@link errorRaysAt}, errors against the double-double reference, medians.
 */
export function errorVsDistance(exponents: number[] = range(0.5, 12, 0.25)): ErrorSeries {
  const f64: ErrorArithmetic = { round: (v) => v, intersect: intersectRaySphere, floor: ERROR_FLOOR };
  const distances = exponents.map((e) => 10 ** e);
  return medianErrorSeries(distances, f64);
}

function range(a: number, b: number, step: number): number[] {
  const xs: number[] = [];
  for (let x = a; x <= b + 1e-9; x += step) xs.push(Math.round(x * 1000) / 1000);
  return xs;
}
