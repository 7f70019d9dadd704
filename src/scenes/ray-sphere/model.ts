/**
 * The ray–sphere scene's model: everything the page shows for one parameter set, as pure functions
 * of the URL parameters calling the core. Nothing here knows about React, SVG or three.js.
 */
import {
  intersectRaySphere,
  raySphereReference,
  type RaySphereHit,
  type RaySphereReference,
} from '../../core/geometry';
import { checkInputs, type InputCheck } from './inputs';
import { methodRow, type MethodRow } from './methodRow';
import type { RaySphereParams } from './params';
import { computeRowsF32, type F32Rows, type Precision } from './precisionF32';

/**
 * Above this |o − C| / r the figures centre on the sphere and leave the origin off screen (the
 * cross-section and the 3D view are then not to scale).
 */
export const FAR_RATIO = 60;

export interface RaySphereModel {
  input: InputCheck;
  /** Null only when even the fallback inputs overflow (then `fatal` says why). */
  chosen: RaySphereHit | null;
  rows: MethodRow[];
  reference: RaySphereReference | null;
  fatal: string | null;
  /** |o − c| / r: how many radii away the sphere's centre is. */
  distanceRatio: number;
  /** The arithmetic of `chosen` (the readouts); `f32`: IEEE single precision, as a shader. */
  precision: Precision;
  /** Both methods in float32, against the reference of the float32 inputs (precisionF32.ts). */
  f32: F32Rows | null;
}

/** The rows and the reference of the model's own precision (those the readouts come from). */
export function activeRows(m: RaySphereModel): { rows: MethodRow[]; reference: RaySphereReference | null } {
  return m.precision === 'f32' && m.f32 ? m.f32 : m;
}

/** Everything the page shows, for one parameter set. */
export function computeModel(
  p: Pick<RaySphereParams, 'o' | 'd' | 'c' | 'r' | 'method'> & { precision?: string },
): RaySphereModel {
  const input = checkInputs(p);
  const { o, d, c, r } = input;
  const ref = raySphereReference(o, d, c, r);
  const distanceRatio = Math.hypot(o[0] - c[0], o[1] - c[1], o[2] - c[2]) / r;
  const precision: Precision = p.precision === 'f32' ? 'f32' : 'f64';
  const f32 = computeRowsF32(input);
  const fail = (fatal: string): RaySphereModel => ({
    input,
    chosen: null,
    rows: [],
    reference: null,
    fatal,
    distanceRatio,
    precision,
    f32,
  });
  if (!ref.ok) return fail(ref.message);
  if (precision === 'f32' && f32.fatal) return fail(f32.fatal);
  const rows: MethodRow[] = [];
  for (const method of ['naive', 'stable'] as const) {
    const res = intersectRaySphere(o, d, c, r, method);
    if (!res.ok) return fail(res.message);
    rows.push(methodRow(method, res, ref));
  }
  const chosen = (precision === 'f32' ? f32.rows : rows).find((row) => row.method === p.method)!.res;
  return { input, chosen, rows, reference: ref, fatal: null, distanceRatio, precision, f32 };
}
