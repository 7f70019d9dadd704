/**
 * The ray–sphere scene in float32 (`precision=f32`): both methods evaluated in IEEE single
 * precision (src/core/geometry/raySphereF32), with their errors against the double-double
 * reference of the same float32 inputs, and the error against distance. Pure functions.
 *
 * The float32 reference is the exact answer for the inputs rounded to float32 (what a shader is
 * given), so the errors shown measure the float32 arithmetic, not the rounding of the typed
 * numbers; the page says when that rounding itself moved an input.
 */
import {
  intersectRaySphereF32,
  raySphereReference,
  relativeError,
  toF32,
  type RaySphereReference,
  type Vec3,
} from '../../core/geometry';
import {
  distantSetup,
  median,
  methodRow,
  relDisc,
  type ErrorSeries,
  type InputCheck,
  type MethodRow,
  type V3,
} from './model';

/** Which arithmetic the readouts use. */
export type Precision = 'f64' | 'f32';

/** Float32 rows (naive, stable) and their reference; null fields with `fatal` when float32 refuses. */
export interface F32Rows {
  rows: MethodRow[];
  reference: RaySphereReference | null;
  fatal: string | null;
  /** True when rounding the inputs to float32 changed any of them. */
  inputsRounded: boolean;
}

/** Both methods in float32 for the checked inputs, against the reference of the float32 inputs. */
export function computeRowsF32(input: InputCheck): F32Rows {
  const o = toF32(input.o);
  const d = toF32(input.d);
  const c = toF32(input.c);
  const r = Math.fround(input.r);
  const inputsRounded =
    [...o, ...d, ...c, r].some((x, i) => x !== [...input.o, ...input.d, ...input.c, input.r][i]) || false;
  const rows: MethodRow[] = [];
  const ref = raySphereReference(o, d, c, r);
  for (const method of ['naive', 'stable'] as const) {
    const res = intersectRaySphereF32(input.o, input.d, input.c, input.r, method);
    if (!res.ok) return { rows: [], reference: null, fatal: res.message, inputsRounded };
    if (!ref.ok) return { rows: [], reference: null, fatal: ref.message, inputsRounded };
    rows.push(methodRow(method, res, ref));
  }
  return { rows, reference: ref.ok ? ref : null, fatal: null, inputsRounded };
}

/** The error series of {@link errorVsDistanceF32}: medians per distance, like the float64 one. */
export type ErrorSeriesF32 = ErrorSeries;

/** Floor for plotting float32 errors on a log axis: exact results plot at u₃₂ = 2⁻²⁴ "or better". */
export const ERROR_FLOOR_F32 = 2 ** -24;

/**
 * The rays of the error-against-distance plot at distance D (as the float64 series in model.ts):
 * from the distant image's eye, aimed at 12 points 0.1 … 0.95 r off the sphere's centre.
 */
export function errorRaysAt(D: number): { eye: Vec3; dirs: Vec3[]; centre: Vec3; r: number } {
  const s = distantSetup(D);
  const dirs: Vec3[] = [];
  for (const rho of [0.1, 0.3, 0.5, 0.7, 0.85, 0.95]) {
    for (const ang of [0.3, 2.1]) {
      const aim: V3 = [0, 1, 2].map(
        (k) => s.centre[k] + rho * (Math.cos(ang) * s.right[k] + Math.sin(ang) * s.up[k]),
      ) as V3;
      dirs.push([aim[0] - s.eye[0], aim[1] - s.eye[1], aim[2] - s.eye[2]]);
    }
  }
  return { eye: s.eye, dirs, centre: s.centre, r: s.r };
}

/**
 * The error of each method in float32 against distance, for the same rays as the float64 plot's
 * `errorVsDistance` ({@link errorRaysAt}), against the double-double reference of the float32
 * inputs. Deterministic.
 */
export function errorVsDistanceF32(
  distances: number[],
  raysAt: (D: number) => { eye: Vec3; dirs: Vec3[]; centre: Vec3; r: number } = errorRaysAt,
): ErrorSeriesF32 {
  const out: ErrorSeriesF32 = { dist: [], discNaive: [], discStable: [], hitNaive: [], hitStable: [] };
  for (const D of distances) {
    const s = raysAt(D);
    const eye = toF32(s.eye);
    const centre = toF32(s.centre);
    const dn: number[] = [];
    const ds: number[] = [];
    const hn: number[] = [];
    const hs: number[] = [];
    for (const dir of s.dirs) {
      const d = toF32(dir);
      const ref = raySphereReference(eye, d, centre, s.r);
      if (!ref.ok) continue;
      for (const method of ['naive', 'stable'] as const) {
        const res = intersectRaySphereF32(eye, d, centre, s.r, method);
        if (!res.ok) continue;
        (method === 'naive' ? dn : ds).push(Math.min(1, relDisc(res.discriminant, ref.discriminant)));
        (method === 'naive' ? hn : hs).push(Math.min(1, relativeError(res.tHit, ref.tHit) ?? 0));
      }
    }
    if (!dn.length || !ds.length) continue;
    out.dist.push(D);
    out.discNaive.push(Math.max(ERROR_FLOOR_F32, median(dn)));
    out.discStable.push(Math.max(ERROR_FLOOR_F32, median(ds)));
    out.hitNaive.push(Math.max(ERROR_FLOOR_F32, median(hn)));
    out.hitStable.push(Math.max(ERROR_FLOOR_F32, median(hs)));
  }
  return out;
}
