/**
 * High-precision reference for ray–sphere intersection in double-double arithmetic (~106 bits),
 * used by the page's precision panel to measure the error of the textbook and robust forms.
 *
 * The inputs are taken as exact doubles. f = o − c is formed exactly (TwoSum), and the
 * discriminant uses Lagrange's identity so that the only cancellation left is the genuine one:
 *
 *     Δ/4 = β² − a c′ = a r² − |d × f|²,   β = f·d,  a = d·d,  c′ = f·f − r².
 *
 * Every product is exact (TwoProduct) and sums carry ~106 bits, so Δ/4 has an absolute error of
 * about 2^-100 · (a r² + |d × f|²): its sign is right except within that band of tangency, far
 * beyond what doubles can resolve. The roots are the stable pair q = −(β + sign(β)√(Δ/4)),
 * t = c′/q, q/a evaluated in double-double. Source: Dekker (1971), Shewchuk (1997) for the
 * arithmetic; Ray Tracing Gems ch. 7 for the formulas. Verified against mathjs BigNumber in tests.
 */
import {
  type DD,
  ddAdd,
  ddDiv,
  ddMul,
  ddNeg,
  ddSign,
  ddSqrt,
  ddSub,
  ddToNumber,
  twoProduct,
  twoSum,
} from './doubleDouble';
import {
  classifyRoots,
  validateRaySphere,
  type RaySphereCase,
  type RaySphereError,
  type Vec3,
} from './raySphere';

/** The reference result: values rounded to the nearest double, plus the double-double Δ/4. */
export interface RaySphereReference {
  ok: true;
  /** Textbook coefficients, correctly rounded-ish (from double-double). */
  a: number;
  b: number;
  c: number;
  /** b² − 4ac (rounded to double from double-double). */
  discriminant: number;
  /** Δ/4 as a double-double, for sign decisions. */
  quarterDiscriminantDD: DD;
  t0: number | null;
  t1: number | null;
  tHit: number | null;
  case: RaySphereCase;
}

/**
 * Double-double reference intersection. Domain and errors as {@link intersectRaySphere}.
 * Tangent policy: exact zero of the double-double Δ (only for inputs that are exactly tangent,
 * such as axis-aligned rays at distance r).
 */
export function raySphereReference(
  o: Vec3,
  d: Vec3,
  c: Vec3,
  r: number,
): RaySphereReference | RaySphereError {
  const bad = validateRaySphere(o, d, c, r);
  if (bad) return bad;
  const f: [DD, DD, DD] = [twoSum(o[0], -c[0]), twoSum(o[1], -c[1]), twoSum(o[2], -c[2])];
  const dv: [DD, DD, DD] = [
    [d[0], 0],
    [d[1], 0],
    [d[2], 0],
  ];
  const a = ddAdd(ddAdd(twoProduct(d[0], d[0]), twoProduct(d[1], d[1])), twoProduct(d[2], d[2]));
  const beta = ddAdd(ddAdd(ddMul(f[0], dv[0]), ddMul(f[1], dv[1])), ddMul(f[2], dv[2]));
  const ff = ddAdd(ddAdd(ddMul(f[0], f[0]), ddMul(f[1], f[1])), ddMul(f[2], f[2]));
  const r2 = twoProduct(r, r);
  const cc = ddSub(ff, r2);
  // d × f, each component a difference of two exact-ish products.
  const cx = ddSub(ddMul(dv[1], f[2]), ddMul(dv[2], f[1]));
  const cy = ddSub(ddMul(dv[2], f[0]), ddMul(dv[0], f[2]));
  const cz = ddSub(ddMul(dv[0], f[1]), ddMul(dv[1], f[0]));
  const cross2 = ddAdd(ddAdd(ddMul(cx, cx), ddMul(cy, cy)), ddMul(cz, cz));
  const q4 = ddSub(ddMul(a, r2), cross2);
  const base = {
    ok: true as const,
    a: ddToNumber(a),
    b: 2 * ddToNumber(beta),
    c: ddToNumber(cc),
    discriminant: 4 * ddToNumber(q4),
    quarterDiscriminantDD: q4,
  };
  const sgn = ddSign(q4);
  if (sgn < 0) return { ...base, t0: null, t1: null, tHit: null, case: 'miss' };
  let t0: number;
  let t1: number;
  if (sgn === 0) {
    t0 = t1 = ddToNumber(ddDiv(ddNeg(beta), a));
  } else {
    const sq = ddSqrt(q4);
    const q = ddNeg(ddSign(beta) >= 0 ? ddAdd(beta, sq) : ddSub(beta, sq));
    const ra = ddToNumber(ddDiv(cc, q));
    const rb = ddToNumber(ddDiv(q, a));
    t0 = Math.min(ra, rb);
    t1 = Math.max(ra, rb);
  }
  const cls = classifyRoots(t0, t1, sgn === 0);
  return { ...base, t0, t1, tHit: cls.tHit, case: cls.case };
}

/**
 * Relative error |x − ref| / |ref| (absolute error when ref = 0). Null in → null out; a missing
 * value where the reference has one (or vice versa) is reported as Infinity ("lost").
 */
export function relativeError(x: number | null, ref: number | null): number | null {
  if (x === null && ref === null) return null;
  if (x === null || ref === null) return Infinity;
  const e = Math.abs(x - ref);
  return ref === 0 ? e : e / Math.abs(ref);
}
