/** One method's result against the double-double reference: its relative errors and whether its case is right. */
import {
  relativeError,
  type RaySphereHit,
  type RaySphereMethod,
  type RaySphereReference,
} from '../../core/geometry';

export interface MethodRow {
  method: RaySphereMethod;
  res: RaySphereHit;
  /** Relative errors against the double-double reference (Infinity = a root lost or invented). */
  errT0: number | null;
  errT1: number | null;
  errHit: number | null;
  errDisc: number | null;
  /** Did the method get the case right? */
  caseRight: boolean;
}

/** The relative error of a discriminant against the reference's (Infinity: a zero made nonzero). */
export function relDisc(x: number, ref: number): number {
  if (ref === 0) return x === 0 ? 0 : Infinity;
  return Math.abs(x - ref) / Math.abs(ref);
}

/** One method's result with its errors against the reference (in float64 or in float32). */
export function methodRow(method: RaySphereMethod, res: RaySphereHit, ref: RaySphereReference): MethodRow {
  return {
    method,
    res,
    errT0: relativeError(res.t0, ref.t0),
    errT1: relativeError(res.t1, ref.t1),
    errHit: relativeError(res.tHit, ref.tHit),
    errDisc: relDisc(res.discriminant, ref.discriminant),
    caseRight: res.case === ref.case,
  };
}
