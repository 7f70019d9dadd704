/**
 * Ray–sphere intersection in IEEE single precision (float32), the arithmetic of a GPU shader,
 * emulated in JavaScript: every input is rounded to float32 and every operation's result is
 * rounded by Math.fround. The formulas and their order are exactly those of ./raySphere.ts (the
 * textbook b² − 4ac and the robust form of Ray Tracing Gems ch. 7), so the two differ only in the
 * precision: u₃₂ = 2⁻²⁴ ≈ 6e-8 instead of u = 2⁻⁵³ ≈ 1.1e-16.
 *
 * Why Math.fround of a double operation is the float32 operation: for +, −, ×, ÷ and √ of two
 * float32 values, the double result rounded to float32 equals the correctly rounded float32
 * result, because a double carries at least 2·24 + 2 significant bits (Figueroa, "When is double
 * rounding innocuous?", SIGNUM 1995). A chain of such steps is therefore bit-exact float32
 * arithmetic, as IEEE 754 prescribes it (no fused multiply–add: a GPU that fuses a·b + c rounds
 * once instead of twice and may differ in the last bits).
 *
 * Consequences (what the tests check): the textbook Δ loses digits like u₃₂ (D/r)², so it is
 * noise by D/r ≈ 1/√u₃₂ = 4096 — a shader meets at 10³–10⁴ what a double meets at 10⁸. The
 * robust Δ loses only like u₃₂ D/r, and its roots stay within a few float32 ulps of the exact
 * ones for the same float32 inputs.
 */
import {
  checkFinite,
  missResult,
  rootsResult,
  type RaySphereHit,
  type RaySphereIntersect,
  type RaySphereResult,
  type Vec3,
} from './raySphere';
import { F32_MAX, U32 } from './ulp32';
import { fail } from '../failure';

const fr = Math.fround;

/** A vector rounded to float32 (each component to the nearest float32). */
export function toF32(v: Vec3): Vec3 {
  return [fr(v[0]), fr(v[1]), fr(v[2])];
}

/** The result of the float32 intersection: the double result's fields, all float32 values. */
export interface RaySphereHitF32 extends RaySphereHit {
  /** The inputs as the float32 computation saw them (rounded from the given doubles). */
  inputs: { o: Vec3; d: Vec3; c: Vec3; r: number };
}

export type RaySphereResultF32 = RaySphereHitF32 | Exclude<RaySphereResult, RaySphereHit>;

/**
 * Intersect the ray o + t d with the sphere |p − c| = r in float32, by the chosen method. The
 * inputs are rounded to float32 first (as a shader receives them); every later operation rounds.
 * Domain: finite inputs, d ≠ 0 and r > 0 after rounding, no float32 overflow of the coefficients
 * (|x| ≤ 3.4e38); else an error result whose message says so. Same cases, tangent policy and
 * roots as {@link intersectRaySphere} (raySphere.ts), evaluated in float32.
 */
export const intersectRaySphereF32: RaySphereIntersect<RaySphereResultF32> = (
  o,
  d,
  c,
  r,
  method = 'stable',
) => {
  const nonFinite = checkFinite(o, d, c, r);
  if (nonFinite) return nonFinite;
  const all = [o[0], o[1], o[2], d[0], d[1], d[2], c[0], c[1], c[2], r];
  const O = toF32(o);
  const D = toF32(d);
  const C = toF32(c);
  const R = fr(r);
  if (!all.every((x) => Math.abs(x) <= F32_MAX)) {
    return fail(
      'overflow',
      'A coordinate is larger than the largest float32 (3.4·10³⁸): it has no float32 value.',
    );
  }
  if (!(R > 0)) {
    return fail(
      'bad-radius',
      `The radius must be positive (got r = ${r} in float32); a sphere with r ≤ 0 has no surface.`,
    );
  }
  const fx = fr(O[0] - C[0]);
  const fy = fr(O[1] - C[1]);
  const fz = fr(O[2] - C[2]);
  const [dx, dy, dz] = D;
  const a = fr(fr(fr(dx * dx) + fr(dy * dy)) + fr(dz * dz));
  if (!(a > 0)) {
    return fail(
      'zero-direction',
      'The direction d is zero (or too short to square in float32, below about 10⁻²³): the ray points nowhere.',
    );
  }
  const beta = fr(fr(fr(fx * dx) + fr(fy * dy)) + fr(fz * dz));
  const b = fr(2 * beta);
  const ff = fr(fr(fr(fx * fx) + fr(fy * fy)) + fr(fz * fz));
  const r2 = fr(R * R);
  const cc = fr(ff - r2);
  const fourA = fr(4 * a);
  const bb = fr(b * b);
  const fourAC = fr(fourA * cc);
  if (![a, b, ff, r2, cc, bb, fourAC].every(Number.isFinite)) {
    return fail(
      'overflow',
      'The numbers are too large for float32: the quadratic’s coefficients overflow (above 3.4·10³⁸).',
    );
  }
  const inputs = { o: O, d: D, c: C, r: R };
  const coef = { a, b, c: cc };
  let disc: number;
  let t0: number;
  let t1: number;
  let nearTangent: boolean;
  if (method === 'naive') {
    disc = fr(bb - fourAC);
    nearTangent = Math.abs(disc) <= 8 * U32 * (bb + Math.abs(fourAC));
    if (disc < 0) return withInputs(missResult(method, coef, disc, nearTangent), inputs);
    const s = fr(Math.sqrt(disc));
    const twoA = fr(2 * a);
    t0 = fr(fr(-b - s) / twoA);
    t1 = fr(fr(-b + s) / twoA);
  } else {
    const k = fr(beta / a);
    const lx = fr(fx - fr(k * dx));
    const ly = fr(fy - fr(k * dy));
    const lz = fr(fz - fr(k * dz));
    const ll = fr(fr(fr(lx * lx) + fr(ly * ly)) + fr(lz * lz));
    const h = fr(r2 - ll);
    const q4 = fr(a * h); // Δ/4
    disc = fr(4 * q4);
    const l = Math.sqrt(ll);
    const f = Math.sqrt(ff);
    nearTangent = Math.abs(h) <= 8 * U32 * (r2 + ll + l * f);
    if (q4 < 0) return withInputs(missResult(method, coef, disc, nearTangent), inputs);
    const sq = fr(Math.sqrt(q4));
    const q = -fr(beta + (beta >= 0 ? sq : -sq));
    if (q === 0) {
      t0 = 0;
      t1 = 0;
    } else {
      const ra = fr(cc / q) + 0; // + 0 turns −0 into +0
      const rb = fr(q / a) + 0;
      t0 = Math.min(ra, rb);
      t1 = Math.max(ra, rb);
    }
  }
  const tangent = disc === 0;
  if (tangent) t0 = t1 = fr(-beta / a) + 0;
  return withInputs(rootsResult(method, coef, disc, t0, t1, tangent, nearTangent), inputs);
};

/** The double routine's result object with the float32 inputs added (no copy). */
function withInputs(hit: RaySphereHit, inputs: RaySphereHitF32['inputs']): RaySphereHitF32 {
  const h = hit as RaySphereHit & Partial<RaySphereHitF32>;
  h.inputs = inputs;
  return h as RaySphereHitF32;
}

/**
 * The nearest hit t ≥ 0 of one ray in float32 (or +∞ for none), for hot loops: the same
 * operations, in the same order, as {@link intersectRaySphereF32} and as the WebGL shader of the
 * ray–sphere scene. All arguments must already be float32 values (the caller rounds them once);
 * r2 = fround(r·r). No allocation.
 */
export function tHitF32(
  ox: number,
  oy: number,
  oz: number,
  dx: number,
  dy: number,
  dz: number,
  cx: number,
  cy: number,
  cz: number,
  r2: number,
  stable: boolean,
): number {
  const fx = fr(ox - cx);
  const fy = fr(oy - cy);
  const fz = fr(oz - cz);
  const a = fr(fr(fr(dx * dx) + fr(dy * dy)) + fr(dz * dz));
  if (!(a > 0)) return Infinity;
  const beta = fr(fr(fr(fx * dx) + fr(fy * dy)) + fr(fz * dz));
  const cc = fr(fr(fr(fr(fx * fx) + fr(fy * fy)) + fr(fz * fz)) - r2);
  let t0: number;
  let t1: number;
  if (stable) {
    const k = fr(beta / a);
    const lx = fr(fx - fr(k * dx));
    const ly = fr(fy - fr(k * dy));
    const lz = fr(fz - fr(k * dz));
    const ll = fr(fr(fr(lx * lx) + fr(ly * ly)) + fr(lz * lz));
    const q4 = fr(a * fr(r2 - ll));
    if (!(q4 >= 0)) return Infinity;
    if (q4 === 0) {
      t0 = t1 = fr(-beta / a);
    } else {
      const sq = fr(Math.sqrt(q4));
      const q = -fr(beta + (beta >= 0 ? sq : -sq));
      const ra = fr(cc / q);
      const rb = fr(q / a);
      t0 = ra < rb ? ra : rb;
      t1 = ra < rb ? rb : ra;
    }
  } else {
    const b = fr(2 * beta);
    const disc = fr(fr(b * b) - fr(fr(4 * a) * cc));
    if (!(disc >= 0)) return Infinity;
    if (disc === 0) {
      t0 = t1 = fr(-beta / a);
    } else {
      const s = fr(Math.sqrt(disc));
      const twoA = fr(2 * a);
      t0 = fr(fr(-b - s) / twoA);
      t1 = fr(fr(-b + s) / twoA);
    }
  }
  return t0 >= 0 ? t0 : t1 >= 0 ? t1 : Infinity;
}
