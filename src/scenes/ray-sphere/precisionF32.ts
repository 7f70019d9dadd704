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
  toF32,
  type RaySphereReference,
} from '../../core/geometry';
import {
  errorRaysAt,
  medianErrorSeries,
  type ErrorArithmetic,
  type ErrorRays,
  type ErrorSeries,
} from './errorSeries';
import type { InputCheck } from './inputs';
import { methodRow, type MethodRow } from './methodRow';

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
 * The error of each method in float32 against distance, for the same rays as the float64 plot's
 * `errorVsDistance` ({@link errorRaysAt}), against the double-double reference of the float32
 * inputs. Deterministic.
 */
export function errorVsDistanceF32(
  distances: number[],
  raysAt: (D: number) => ErrorRays = errorRaysAt,
): ErrorSeriesF32 {
  const f32: ErrorArithmetic = { round: toF32, intersect: intersectRaySphereF32, floor: ERROR_FLOOR_F32 };
  return medianErrorSeries(distances, f32, raysAt);
}
