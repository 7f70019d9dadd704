/**
 * Ray–sphere intersection, two ways: the textbook quadratic and the robust form of
 * Haines, Günther & Akenine-Möller, "Precision Improvements for Ray/Sphere Intersection",
 * Ray Tracing Gems (2019), chapter 7. The ray is p(t) = o + t d (d need not be unit length:
 * t is then measured in units of d); the sphere has centre c and radius r > 0.
 *
 * Substituting the ray into |p − c|² = r² with f = o − c gives
 *
 *     a t² + b t + c′ = 0,   a = d·d,   b = 2 f·d,   c′ = f·f − r²,   Δ = b² − 4 a c′.
 *
 * Textbook form: Δ = b² − 4ac′ and t = (−b ± √Δ) / 2a, evaluated as written. When the sphere
 * is far away (|f| ≫ r) both b² and 4ac′ are ≈ 4a|f|² and their difference, ≈ 4a r², is lost
 * to cancellation: the relative error of Δ grows like ε (|f|/r)², so at |f| ≈ 1e8 r the sign of Δ
 * is noise (speckled holes in a render). −b ± √Δ also cancels for the root nearer 0.
 *
 * Robust form (RTG ch. 7, eqs. 7.4–7.8, written for a non-unit d): with β = f·d (so b = 2β),
 * l = f − (β/a) d is the vector from the centre to the closest point of the line, and
 *
 *     Δ/4 = β² − a c′ = a (r² − |l|²)          (Lagrange's identity: |d × f|² = a |l|²)
 *
 * has no cancellation between large terms: its relative error grows only like ε |f|/r. The roots
 * come from the stable pair q = −(β + sign(β) √(Δ/4)), t = c′/q and t = q/a (Press et al.,
 * Numerical Recipes §5.6), which never subtracts nearly equal numbers.
 *
 * Cases (what the ray, t ≥ 0, sees):
 *   'miss'     Δ < 0: the line passes the sphere, no real root;
 *   'tangent'  Δ = 0 exactly (see the tangent policy below) and the double root t ≥ 0;
 *   'two-hits' 0 ≤ t0 < t1: enters at t0 (the hit) and leaves at t1;
 *   'inside'   t0 < 0 ≤ t1: the origin is inside (or on) the sphere, the hit is t1;
 *   'behind'   Δ ≥ 0 but t1 < 0: the line meets the sphere behind the origin, no hit.
 *
 * Tangent policy: 'tangent' means the computed discriminant is exactly zero, for both methods;
 * t0 = t1 = −b/2a then. Nothing is snapped: a ray one ulp past tangent is a miss if the method's
 * Δ says so. Separately, `nearTangent` reports that |Δ| is within the method's own rounding-error
 * bound (the sign of the computed Δ is then not trustworthy); see {@link raySphereErrorBound}.
 * A tangent point behind the origin (double root < 0) is 'behind'. The origin exactly on the
 * surface gives a root t = 0, which counts as a hit (t ≥ 0).
 */
import { fail, type Failure } from '../failure';

import type { Vec3 } from '../vec3';

export type { Vec3 };

/** Which evaluation of the quadratic: the textbook b² − 4ac, or the robust RTG ch. 7 form. */
export type RaySphereMethod = 'naive' | 'stable';

/** What the ray sees; see the module comment for the exact rules. */
export type RaySphereCase = 'miss' | 'tangent' | 'two-hits' | 'inside' | 'behind';

/** Why the inputs do not describe a ray and a sphere. */
export type RaySphereErrorKind = 'non-finite' | 'zero-direction' | 'bad-radius' | 'overflow';

/** A successful intersection: coefficients, discriminant, roots and case. */
export interface RaySphereHit {
  ok: true;
  method: RaySphereMethod;
  /** Textbook coefficients of a t² + b t + c = 0 (always evaluated as a = d·d, b = 2 d·(o−c), c = |o−c|² − r²). */
  a: number;
  b: number;
  c: number;
  /** Discriminant in the meaning b² − 4ac, evaluated by `method` (robust: 4a(r² − |l|²)). */
  discriminant: number;
  /** Roots, ascending (t0 ≤ t1); null on a miss. */
  t0: number | null;
  t1: number | null;
  /** Nearest root with t ≥ 0, or null (miss or behind). */
  tHit: number | null;
  case: RaySphereCase;
  /** |Δ| is within the method's rounding-error bound: the sign of Δ is not trustworthy. */
  nearTangent: boolean;
}

/** Inputs that are not a ray and a sphere; `message` is written for the page. */
export type RaySphereError = Failure<RaySphereErrorKind>;

export type RaySphereResult = RaySphereHit | RaySphereError;

/**
 * An intersection routine: the ray o + t d against the sphere |p − c| = r by `method` (default
 * 'stable'), in one precision: {@link intersectRaySphere} in double, intersectRaySphereF32 in float32.
 */
export type RaySphereIntersect<R> = (o: Vec3, d: Vec3, c: Vec3, r: number, method?: RaySphereMethod) => R;

const EPS = Number.EPSILON / 2; // unit roundoff u = 2^-53

/** The first check of every method and precision: all ten numbers finite, else the error. */
export function checkFinite(o: Vec3, d: Vec3, c: Vec3, r: number): RaySphereError | null {
  const all = [o[0], o[1], o[2], d[0], d[1], d[2], c[0], c[1], c[2], r];
  if (all.every(Number.isFinite)) return null;
  return fail('non-finite', 'Every coordinate and the radius must be finite numbers.');
}

/**
 * Check that (o, d, c, r) describe a ray and a sphere. Returns null when fine, else the error.
 * Rules: every number finite; d·d > 0 (a zero or underflowing direction has no t); r > 0;
 * the coefficients must not overflow.
 */
export function validateRaySphere(o: Vec3, d: Vec3, c: Vec3, r: number): RaySphereError | null {
  const nonFinite = checkFinite(o, d, c, r);
  if (nonFinite) return nonFinite;
  if (!(r > 0)) {
    return fail(
      'bad-radius',
      `The radius must be positive (got r = ${r}); a sphere with r ≤ 0 has no surface.`,
    );
  }
  const a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  if (!(a > 0)) {
    return fail(
      'zero-direction',
      'The direction d is zero (or too short to square in double precision): the ray points nowhere.',
    );
  }
  const fx = o[0] - c[0];
  const fy = o[1] - c[1];
  const fz = o[2] - c[2];
  const ff = fx * fx + fy * fy + fz * fz;
  const b = 2 * (fx * d[0] + fy * d[1] + fz * d[2]);
  // Keep every intermediate (b², 4a·|f|², 4a·r², and the double-double reference's Veltkamp
  // splits, which need |x| ≤ 2^996) finite: refuse coefficients beyond 2^960 ≈ 1e289.
  const LIMIT = 2 ** 960;
  if (!(a <= LIMIT && b * b <= LIMIT && 4 * a * ff <= LIMIT && 4 * a * r * r <= LIMIT && ff <= LIMIT)) {
    return fail(
      'overflow',
      'The numbers are too large: the quadratic’s coefficients overflow double precision.',
    );
  }
  return null;
}

/** Textbook coefficients a = d·d, b = 2 d·(o − c), c = |o − c|² − r² (double arithmetic, as written). */
export function raySphereCoefficients(
  o: Vec3,
  d: Vec3,
  c: Vec3,
  r: number,
): { a: number; b: number; c: number } {
  const fx = o[0] - c[0];
  const fy = o[1] - c[1];
  const fz = o[2] - c[2];
  return {
    a: d[0] * d[0] + d[1] * d[1] + d[2] * d[2],
    b: 2 * (fx * d[0] + fy * d[1] + fz * d[2]),
    c: fx * fx + fy * fy + fz * fz - r * r,
  };
}

/**
 * Classify sorted roots (t0 ≤ t1) by the rules in the module comment.
 * `tangent` is the method's exact-zero discriminant flag.
 */
export function classifyRoots(
  t0: number,
  t1: number,
  tangent: boolean,
): { case: RaySphereCase; tHit: number | null } {
  if (t1 < 0) return { case: 'behind', tHit: null };
  if (tangent) return { case: 'tangent', tHit: t1 };
  if (t0 >= 0) return { case: 'two-hits', tHit: t0 };
  return { case: 'inside', tHit: t1 };
}

/**
 * Intersect the ray o + t d (t ∈ ℝ, hits need t ≥ 0) with the sphere |p − c| = r by the chosen
 * method. Domain: finite inputs, d ≠ 0, r > 0 (else an error result, never NaN). Measure: t in
 * units of |d|. Source: Ray Tracing Gems ch. 7 (robust), Shirley, Ray Tracing in One Weekend §5–6
 * (textbook).
 */
export const intersectRaySphere: RaySphereIntersect<RaySphereResult> = (o, d, c, r, method = 'stable') => {
  const bad = validateRaySphere(o, d, c, r);
  if (bad) return bad;
  const coef = raySphereCoefficients(o, d, c, r);
  const { a, b } = coef;
  const cc = coef.c;
  const fx = o[0] - c[0];
  const fy = o[1] - c[1];
  const fz = o[2] - c[2];
  const beta = b / 2; // exact: halving a double
  let disc: number; // in the meaning b² − 4ac
  let t0: number;
  let t1: number;
  let nearTangent: boolean;
  if (method === 'naive') {
    disc = b * b - 4 * a * cc;
    nearTangent = Math.abs(disc) <= 8 * EPS * (b * b + Math.abs(4 * a * cc));
    if (disc < 0) return missResult(method, coef, disc, nearTangent);
    const s = Math.sqrt(disc);
    t0 = (-b - s) / (2 * a);
    t1 = (-b + s) / (2 * a);
  } else {
    const k = beta / a;
    const lx = fx - k * d[0];
    const ly = fy - k * d[1];
    const lz = fz - k * d[2];
    const ll = lx * lx + ly * ly + lz * lz;
    const r2 = r * r;
    const q4 = a * (r2 - ll); // Δ/4
    disc = 4 * q4;
    nearTangent = Math.abs(r2 - ll) <= raySphereErrorBound(o, d, c, r);
    if (q4 < 0) return missResult(method, coef, disc, nearTangent);
    const sq = Math.sqrt(q4);
    const q = -(beta + (beta >= 0 ? sq : -sq));
    if (q === 0) {
      // β = 0 and Δ = 0: c′ = 0 too, the double root is t = 0 (origin on the surface, d tangent).
      t0 = 0;
      t1 = 0;
    } else {
      const ra = cc / q + 0; // + 0 turns −0 into +0
      const rb = q / a + 0;
      t0 = Math.min(ra, rb);
      t1 = Math.max(ra, rb);
    }
  }
  const tangent = disc === 0;
  if (tangent) {
    t0 = t1 = -beta / a;
  }
  return rootsResult(method, coef, disc, t0, t1, tangent, nearTangent);
};

/** The coefficients a, b, c of the quadratic, as a method evaluated them. */
export interface RaySphereCoefficients {
  a: number;
  b: number;
  c: number;
}

/**
 * The result for real roots t0 ≤ t1 (either precision): the case and the hit by
 * {@link classifyRoots}; `tangent` is the method's exact-zero discriminant flag.
 */
export function rootsResult(
  method: RaySphereMethod,
  coef: RaySphereCoefficients,
  disc: number,
  t0: number,
  t1: number,
  tangent: boolean,
  nearTangent: boolean,
): RaySphereHit {
  const cls = classifyRoots(t0, t1, tangent);
  return hitResult(method, coef, disc, t0, t1, cls.tHit, cls.case, nearTangent);
}

/** The result for a negative discriminant (either precision): no real root. */
export function missResult(
  method: RaySphereMethod,
  coef: RaySphereCoefficients,
  disc: number,
  nearTangent: boolean,
): RaySphereHit {
  return hitResult(method, coef, disc, null, null, null, 'miss', nearTangent);
}

// One object literal for every successful result, so that all of them share one shape.
function hitResult(
  method: RaySphereMethod,
  coef: RaySphereCoefficients,
  disc: number,
  t0: number | null,
  t1: number | null,
  tHit: number | null,
  kind: RaySphereCase,
  nearTangent: boolean,
): RaySphereHit {
  const { a, b, c } = coef;
  return { ok: true, method, a, b, c, discriminant: disc, t0, t1, tHit, case: kind, nearTangent };
}

/**
 * A first-order bound on the absolute rounding error of r² − |l|² in the robust form: about
 * 8u·(r² + |l|² + |l|·|f|) where u = 2^-53 (the |l||f| term is the cancellation in l = f − (β/a)d,
 * whose components carry an absolute error ≲ 3u|f|). Used only for the `nearTangent` flag.
 * Domain: validated inputs. Source: standard forward error analysis (Higham, Accuracy and
 * Stability of Numerical Algorithms, ch. 3).
 */
export function raySphereErrorBound(o: Vec3, d: Vec3, c: Vec3, r: number): number {
  const fx = o[0] - c[0];
  const fy = o[1] - c[1];
  const fz = o[2] - c[2];
  const a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const k = (fx * d[0] + fy * d[1] + fz * d[2]) / a;
  const lx = fx - k * d[0];
  const ly = fy - k * d[1];
  const lz = fz - k * d[2];
  const l = Math.hypot(lx, ly, lz);
  const f = Math.hypot(fx, fy, fz);
  return 8 * EPS * (r * r + l * l + l * f);
}

/** Stride of one ray in a batched ray buffer: ox, oy, oz, dx, dy, dz. */
export const RAY_STRIDE = 6;

/** Sentinel written by the batched kernel for "no hit with t ≥ 0" (as in most ray tracers). */
export const NO_HIT = Infinity;

/**
 * Batched kernel: nearest hit t ≥ 0 of `count` rays against one sphere, by the chosen method.
 * rays: Float64Array of count·6 numbers (o then d per ray); out: caller-owned Float64Array of
 * length ≥ count, receives t-hit or {@link NO_HIT} (= +∞) for a miss or a sphere behind.
 * No allocation per ray. Same rules as {@link intersectRaySphere} (tangent counts as a hit,
 * t = 0 counts); rays with d = 0 write NO_HIT. r must be > 0 and finite. Returns the hit count.
 */
export function intersectRaySphereBatch(
  rays: Float64Array,
  count: number,
  cx: number,
  cy: number,
  cz: number,
  r: number,
  method: RaySphereMethod,
  out: Float64Array,
): number {
  const r2 = r * r;
  let hits = 0;
  const stable = method === 'stable';
  for (let i = 0, j = 0; i < count; i++, j += RAY_STRIDE) {
    const fx = rays[j] - cx;
    const fy = rays[j + 1] - cy;
    const fz = rays[j + 2] - cz;
    const dx = rays[j + 3];
    const dy = rays[j + 4];
    const dz = rays[j + 5];
    const a = dx * dx + dy * dy + dz * dz;
    const beta = fx * dx + fy * dy + fz * dz;
    const cc = fx * fx + fy * fy + fz * fz - r2;
    let t = NO_HIT;
    if (a > 0) {
      if (stable) {
        const k = beta / a;
        const lx = fx - k * dx;
        const ly = fy - k * dy;
        const lz = fz - k * dz;
        const q4 = a * (r2 - (lx * lx + ly * ly + lz * lz));
        if (q4 >= 0) {
          const sq = Math.sqrt(q4);
          const q = -(beta + (beta >= 0 ? sq : -sq));
          let t0: number;
          let t1: number;
          if (q === 0) {
            t0 = 0;
            t1 = 0;
          } else {
            const ra = cc / q + 0;
            const rb = q / a + 0;
            t0 = ra < rb ? ra : rb;
            t1 = ra < rb ? rb : ra;
          }
          if (q4 === 0) t0 = t1 = -beta / a;
          t = t0 >= 0 ? t0 : t1 >= 0 ? t1 : NO_HIT;
        }
      } else {
        const b = 2 * beta;
        const disc = b * b - 4 * a * cc;
        if (disc >= 0) {
          const s = Math.sqrt(disc);
          const t0 = (-b - s) / (2 * a);
          const t1 = (-b + s) / (2 * a);
          t = t0 >= 0 ? t0 : t1 >= 0 ? t1 : NO_HIT;
        }
      }
    }
    out[i] = t;
    if (t !== NO_HIT) hits++;
  }
  return hits;
}

/**
 * Fill `rays` (Float64Array, ≥ w·h·6) with one pinhole-camera ray per pixel centre, row-major,
 * top row first. The camera sits at `eye`, looks along unit `forward` with unit `right` and `up`
 * (orthonormal), and the image spans ±halfWidth along right and ±halfWidth·h/w along up at unit
 * distance. Directions are normalised (so t is a distance). No allocation.
 */
export function fillPinholeRays(
  rays: Float64Array,
  w: number,
  h: number,
  eye: Vec3,
  forward: Vec3,
  right: Vec3,
  up: Vec3,
  halfWidth: number,
): void {
  const halfHeight = (halfWidth * h) / w;
  for (let y = 0, j = 0; y < h; y++) {
    const sy = halfHeight * (1 - (2 * (y + 0.5)) / h);
    for (let x = 0; x < w; x++, j += RAY_STRIDE) {
      const sx = halfWidth * ((2 * (x + 0.5)) / w - 1);
      let dx = forward[0] + sx * right[0] + sy * up[0];
      let dy = forward[1] + sx * right[1] + sy * up[1];
      let dz = forward[2] + sx * right[2] + sy * up[2];
      const inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
      dx *= inv;
      dy *= inv;
      dz *= inv;
      rays[j] = eye[0];
      rays[j + 1] = eye[1];
      rays[j + 2] = eye[2];
      rays[j + 3] = dx;
      rays[j + 4] = dy;
      rays[j + 5] = dz;
    }
  }
}
