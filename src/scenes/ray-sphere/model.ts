/**
 * The ray–sphere scene's model: pure functions of the URL parameters, calling the core.
 * Nothing here knows about React, SVG, three.js or Plotly.
 */
import {
  intersectRaySphere,
  intersectRaySphereBatch,
  raySphereReference,
  relativeError,
  fillPinholeRays,
  RAY_STRIDE,
  NO_HIT,
  type RaySphereCase,
  type RaySphereHit,
  type RaySphereMethod,
  type RaySphereReference,
  type RaySphereResult,
  type Vec3,
} from '../../core/geometry';
import { fail, type Failure } from '../../core/failure';
import { schema, type RaySphereParams } from './params';
import { computeRowsF32, type F32Rows, type Precision } from './precisionF32';

export type V3 = [number, number, number];

/**
 * Above this |o − C| / r the figures centre on the sphere and leave the origin off screen (the
 * cross-section and the 3D view are then not to scale).
 */
export const FAR_RATIO = 60;

/** Plain-words explanation of each case, shown beside the case name. */
export const CASE_TEXT: Record<RaySphereCase, string> = {
  miss: 'Δ < 0: the quadratic has no real root, so the line never touches the sphere.',
  tangent: 'Δ = 0: one double root; the ray just touches the sphere at t = −b / 2a.',
  'two-hits':
    'Δ > 0 and both roots ≥ 0: the ray enters at t₀ and leaves at t₁. The hit is the nearest root ≥ 0, t₀.',
  inside:
    'Δ > 0 with t₀ < 0 ≤ t₁: the origin is inside the sphere. t₀ lies behind the origin, so the hit is t₁ (the exit).',
  behind:
    'Δ ≥ 0 but every root is < 0: the line meets the sphere behind the origin. A ray only goes forward (t ≥ 0), so there is no hit.',
};

export interface InputCheck {
  /** The values actually used (bad ones replaced by safe fallbacks). */
  o: V3;
  d: V3;
  c: V3;
  r: number;
  /** What was replaced and why (kind for code, message for the page); empty when the inputs are fine. */
  failures: Failure<InputProblem>[];
  /** The failures' messages, in order. */
  problems: string[];
}

/** Why an input was replaced by a safe value. */
export type InputProblem =
  'not-finite' | 'zero-radius' | 'negative-radius' | 'zero-direction' | 'direction-underflow';

const DEFAULT_D: V3 = [...schema.d.default];

/**
 * Replace inputs that do not describe a ray and a sphere by safe values, saying why:
 * non-finite numbers → defaults; d = 0 (or too short to square) → the default direction;
 * r ≤ 0 → |r| if positive, else 1.
 */
export function checkInputs(p: Pick<RaySphereParams, 'o' | 'd' | 'c' | 'r'>): InputCheck {
  const failures: Failure<InputProblem>[] = [];
  const fin = (v: readonly number[], name: string, fallback: readonly number[]): V3 => {
    if (v.length === 3 && v.every(Number.isFinite)) return [v[0], v[1], v[2]];
    failures.push(
      fail('not-finite', `${name} has a value that is not a finite number; using ${fallback.join(', ')}.`),
    );
    return [fallback[0], fallback[1], fallback[2]];
  };
  const o = fin(p.o, 'The origin o', schema.o.default);
  let d = fin(p.d, 'The direction d', schema.d.default);
  const c = fin(p.c, 'The centre C', schema.c.default);
  let r = p.r;
  if (!Number.isFinite(r)) {
    failures.push(fail('not-finite', `The radius is not a finite number; using r = ${schema.r.default}.`));
    r = schema.r.default;
  } else if (r <= 0) {
    const fb = r < 0 ? -r : schema.r.default;
    failures.push(
      r === 0
        ? fail('zero-radius', `A radius of 0 is a point, not a sphere; using r = ${fb}.`)
        : fail(
            'negative-radius',
            `A negative radius (r = ${r}) does not describe a sphere; using |r| = ${fb}.`,
          ),
    );
    r = fb;
  }
  const a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  if (!(a > 0)) {
    const using = `using d = (${DEFAULT_D.join(', ')})`;
    failures.push(
      d.every((x) => x === 0)
        ? fail('zero-direction', `The direction d = (0, 0, 0) points nowhere, so the ray has no t; ${using}.`)
        : fail(
            'direction-underflow',
            `The direction d is too short to square in double precision (d·d underflows to 0); ${using}.`,
          ),
    );
    d = [...DEFAULT_D];
  }
  return { o, d, c, r, failures, problems: failures.map((f) => f.message) };
}

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

/** g(t) = a t² + b t + c sampled for the plot, over a window that shows the vertex and the roots. */
export function gCurve(
  res: RaySphereHit,
  samples = 161,
): { t: number[]; g: number[]; tMin: number; tMax: number } {
  const { a, b } = res;
  const tv = -b / (2 * a);
  let half: number;
  if (res.t0 !== null && res.t1 !== null && res.t1 > res.t0) half = 1.6 * (res.t1 - res.t0);
  else half = Math.sqrt(Math.abs(res.discriminant)) / a;
  // include t = 0 when it is not absurdly far from the action
  if (!(half > 0) || !Number.isFinite(half)) half = 1;
  let tMin = tv - half;
  let tMax = tv + half;
  if (Math.abs(tv) < 4 * half) {
    tMin = Math.min(tMin, -0.15 * half);
    tMax = Math.max(tMax, 0.15 * half);
  }
  const t: number[] = [];
  const g: number[] = [];
  for (let i = 0; i < samples; i++) {
    const x = tMin + ((tMax - tMin) * i) / (samples - 1);
    t.push(x);
    // vertex form: a (t − t_v)² − Δ/4a, accurate where the expanded form would cancel
    g.push(a * (x - tv) * (x - tv) - res.discriminant / (4 * a));
  }
  return { t, g, tMin, tMax };
}

// ---------------------------------------------------------------------------------------------
// 2D cross-section through the ray and the centre.

export interface Frame2D {
  /** Anchor (the centre at the time the frame was made) and orthonormal in-plane axes. */
  p: V3;
  e1: V3;
  e2: V3;
}

const dot = (x: readonly number[], y: readonly number[]) => x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
const sub = (x: readonly number[], y: readonly number[]): V3 => [x[0] - y[0], x[1] - y[1], x[2] - y[2]];
const scale = (x: readonly number[], s: number): V3 => [x[0] * s, x[1] * s, x[2] * s];
const norm = (x: readonly number[]) => Math.hypot(x[0], x[1], x[2]);
const cross = (x: readonly number[], y: readonly number[]): V3 => [
  x[1] * y[2] - x[2] * y[1],
  x[2] * y[0] - x[0] * y[2],
  x[0] * y[1] - x[1] * y[0],
];

/**
 * l = f − (f·d / d·d) d with f = o − C: from the centre to the closest point of the ray's line
 * (the vector of the robust form); |l| is the line's distance from the centre.
 */
export function closestOffset(o: Vec3, d: Vec3, c: Vec3): V3 {
  const f = sub(o, c);
  return sub(f, scale(d, dot(f, d) / dot(d, d)));
}

/** The distance of the ray's line from the centre: the closest approach (tangent when it is r). */
export const closestApproach = (o: Vec3, d: Vec3, c: Vec3) => norm(closestOffset(o, d, c));

/**
 * The canonical frame: e1 along d, e2 from the centre towards the ray's line (the ray then runs
 * horizontally above the centre), anchored at the centre. If the centre is on the line, e2 is the
 * in-plane direction closest to world z (or y).
 */
export function canonicalFrame(o: Vec3, d: Vec3, c: Vec3): Frame2D {
  const e1 = scale(d, 1 / norm(d));
  const f = sub(o, c);
  const l = sub(f, scale(e1, dot(f, e1)));
  const ln = norm(l);
  let e2: V3;
  if (ln > 1e-12 * (norm(f) + 1e-300)) e2 = scale(l, 1 / ln);
  else {
    const up: V3 = Math.abs(e1[2]) < 0.9 ? [0, 0, 1] : [0, 1, 0];
    const w = sub(up, scale(e1, dot(up, e1)));
    e2 = scale(w, 1 / norm(w));
  }
  return { p: [c[0], c[1], c[2]], e1, e2 };
}

/** Is the ray's line and the centre (still) in the frame's plane, to a tolerance `tol` in length? */
export function frameFits(fr: Frame2D, o: Vec3, d: Vec3, c: Vec3, tol: number): boolean {
  const n = cross(fr.e1, fr.e2);
  const dn = Math.abs(dot(d, n)) / norm(d);
  return Math.abs(dot(sub(o, fr.p), n)) <= tol && Math.abs(dot(sub(c, fr.p), n)) <= tol && dn <= 1e-9;
}

/** World → frame coordinates (x along e1, y along e2). */
export function toFrame(fr: Frame2D, q: Vec3): [number, number] {
  const v = sub(q, fr.p);
  return [dot(v, fr.e1), dot(v, fr.e2)];
}

/** Frame → world coordinates. */
export function fromFrame(fr: Frame2D, x: number, y: number): V3 {
  return [
    fr.p[0] + x * fr.e1[0] + y * fr.e2[0],
    fr.p[1] + x * fr.e1[1] + y * fr.e2[1],
    fr.p[2] + x * fr.e1[2] + y * fr.e2[2],
  ];
}

/** In-plane direction → world direction. */
export function dirFromFrame(fr: Frame2D, x: number, y: number): V3 {
  return [x * fr.e1[0] + y * fr.e2[0], x * fr.e1[1] + y * fr.e2[1], x * fr.e1[2] + y * fr.e2[2]];
}

/** Round to a step chosen from the view size (keeps dragged values and URLs tidy). */
export function tidy(x: number, step: number): number {
  const y = Math.round(x / step) * step;
  const digits = Math.max(0, Math.min(15, -Math.floor(Math.log10(step))));
  return Number(y.toFixed(digits));
}

// ---------------------------------------------------------------------------------------------
// The rendered image of a distant sphere, one ray per pixel, both methods.

export interface DistantImage {
  width: number;
  height: number;
  /** t-hit per pixel for each method (NO_HIT = ∞ for none). */
  naive: Float64Array;
  stable: Float64Array;
  /** Pixel counts: hits by each method, and pixels where the two disagree. */
  naiveHits: number;
  stableHits: number;
  disagree: number;
  /** Milliseconds spent filling rays and running both batched kernels. */
  ms: number;
}

/** The camera and sphere of the distant-sphere image: the sphere's centre is `dist` radii away. */
export function distantSetup(dist: number): {
  eye: V3;
  centre: V3;
  r: number;
  forward: V3;
  right: V3;
  up: V3;
  halfWidth: number;
} {
  const eye: V3 = [0.1, -0.2, 0.05];
  const dir = [1, 0.3, 0.2];
  const n = Math.hypot(dir[0], dir[1], dir[2]);
  const forward: V3 = [dir[0] / n, dir[1] / n, dir[2] / n];
  const centre: V3 = [eye[0] + dist * forward[0], eye[1] + dist * forward[1], eye[2] + dist * forward[2]];
  const rightRaw = cross(forward, [0, 0, 1]);
  const right = scale(rightRaw, 1 / norm(rightRaw));
  const up = cross(right, forward);
  // frame the sphere: it fills ~70% of the width
  const halfWidth = 1.45 / Math.sqrt(dist * dist - 1);
  return { eye, centre, r: 1, forward, right, up, halfWidth };
}

/** Scratch buffers reused between renders (caller-owned in spirit: one image size at a time). */
let scratchRays: Float64Array | null = null;

/**
 * Render the distant sphere with both methods into fresh t buffers. `now` is a clock (injected so
 * the model stays pure of the DOM; pass performance.now in the view).
 */
export function renderDistant(
  dist: number,
  width: number,
  height: number,
  now: () => number = () => 0,
): DistantImage {
  const n = width * height;
  if (!scratchRays || scratchRays.length < n * RAY_STRIDE) scratchRays = new Float64Array(n * RAY_STRIDE);
  const s = distantSetup(dist);
  const naive = new Float64Array(n);
  const stable = new Float64Array(n);
  const t0 = now();
  fillPinholeRays(scratchRays, width, height, s.eye, s.forward, s.right, s.up, s.halfWidth);
  const naiveHits = intersectRaySphereBatch(
    scratchRays,
    n,
    s.centre[0],
    s.centre[1],
    s.centre[2],
    s.r,
    'naive',
    naive,
  );
  const stableHits = intersectRaySphereBatch(
    scratchRays,
    n,
    s.centre[0],
    s.centre[1],
    s.centre[2],
    s.r,
    'stable',
    stable,
  );
  const ms = now() - t0;
  let disagree = 0;
  for (let i = 0; i < n; i++) if ((naive[i] === NO_HIT) !== (stable[i] === NO_HIT)) disagree++;
  return { width, height, naive, stable, naiveHits, stableHits, disagree, ms };
}

/**
 * Shade a t buffer into RGBA pixels (caller-owned `out`, length 4·n): hits get a Lambert-ish shade
 * from the depth offset relative to the nearest hit (front of the sphere brighter), misses the
 * background; `hole` pixels (hit by `other` but not by this method) are marked in `holeRGB`.
 */
export function shadeImage(
  t: Float64Array,
  other: Float64Array | null,
  r: number,
  out: Uint8ClampedArray,
  bg: V3,
  fg: V3,
  holeRGB: V3,
): void {
  let tMin = Infinity;
  for (let i = 0; i < t.length; i++) if (t[i] < tMin) tMin = t[i];
  for (let i = 0, j = 0; i < t.length; i++, j += 4) {
    const ti = t[i];
    let col: V3;
    if (ti === NO_HIT) col = other && other[i] !== NO_HIT ? holeRGB : bg;
    else {
      // depth δ behind the nearest point: cos θ = 1 − δ/r between the normal and the view ray
      const cosTheta = Math.min(1, Math.max(0, 1 - (ti - tMin) / r));
      const shade = 0.3 + 0.7 * cosTheta;
      col = [fg[0] * shade, fg[1] * shade, fg[2] * shade];
    }
    out[j] = col[0];
    out[j + 1] = col[1];
    out[j + 2] = col[2];
    out[j + 3] = 255;
  }
}

// ---------------------------------------------------------------------------------------------
// Error against distance.

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
      const aim: V3 = [0, 1, 2].map(
        (k) => s.centre[k] + rho * (Math.cos(ang) * s.right[k] + Math.sin(ang) * s.up[k]),
      ) as V3;
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

// ---------------------------------------------------------------------------------------------
// The sweep animation: the ray moves across the sphere as the timeline's t goes 0 → 1.
// Everything on screen at position t is a pure function of the parameters and t.

export type SweepMode = 'offset' | 'rotate';

export interface Sweep {
  mode: SweepMode;
  /** Extent E: the origin moves ±E r (offset), or the direction turns ±E α (rotate). */
  extent: number;
  /** The configuration the sweep is centred on (t = 0.5): the checked inputs. */
  base: InputCheck;
  /** In-plane frame of the base configuration: e1 = d / |d|, e2 from C towards the line. */
  e1: V3;
  e2: V3;
  /** Signed distance of the base line from C along e2 (= |l| ≥ 0). */
  h0: number;
  /** |d| and |o − C| of the base configuration. */
  dl: number;
  dist: number;
  /** The sphere's angular radius seen from o: asin(min(1, r / |o − C|)); π/2 from inside. */
  alpha: number;
  /** Angle (in the e1, e2 plane) of the direction from o towards C. */
  omega: number;
}

/** The sweep's frame and constants for one parameter set (t-independent). */
export function makeSweep(input: InputCheck, mode: SweepMode, extent: number): Sweep {
  const { o, d, c, r } = input;
  const fr = canonicalFrame(o, d, c);
  const f = sub(o, c);
  const dist = norm(f);
  // l = f − (f·d / d·d) d: from C to the closest point of the line (as in the robust form); its
  // length is the line's distance from C. e2 = l / |l|, made exactly perpendicular to e1 again
  // (for a far sphere l's direction carries the rounding of f·d, and f·e2 would cancel to 0).
  const e1 = fr.e1;
  const l = closestOffset(o, d, c);
  const h0 = norm(l);
  let e2: V3 = fr.e2;
  if (h0 > 0 && Number.isFinite(h0)) {
    let w = scale(l, 1 / h0);
    w = sub(w, scale(e1, dot(w, e1)));
    const wn = norm(w);
    if (wn > 0.5) e2 = scale(w, 1 / wn);
  }
  const alpha = dist > r ? Math.asin(r / dist) : Math.PI / 2;
  // direction from o to C in the (e1, e2) plane: −f = −(f·e1) e1 − h0 e2
  const omega = Math.atan2(-h0, -dot(f, e1));
  return {
    mode,
    extent: Number.isFinite(extent) && extent > 0 ? extent : 2.5,
    base: input,
    e1,
    e2,
    h0,
    dl: norm(d),
    dist,
    alpha,
    omega,
  };
}

export interface SweepState {
  t: number;
  o: V3;
  d: V3;
  /**
   * The sweep coordinate drawn on the Δ plot's x axis. Offset: the signed distance of the line
   * from C in radii, h / r (tangent at ±1). Rotate: the angle between d and the direction to C in
   * angular radii, ψ / α (tangent at ±1 when the origin is outside).
   */
  x: number;
}

/** Where the ray is at timeline position t ∈ [0, 1] (t = 0.5: the configuration typed in o, d). */
export function sweepAt(sw: Sweep, t: number): SweepState {
  const u = 2 * Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0.5)) - 1;
  const { o, d, r } = sw.base;
  if (u === 0) {
    // exactly the typed configuration (no rounding from adding zero offsets)
    return {
      t,
      o: [o[0], o[1], o[2]],
      d: [d[0], d[1], d[2]],
      x: sw.mode === 'offset' ? sw.h0 / r : psi(sw, 0),
    };
  }
  if (sw.mode === 'offset') {
    const s = u * sw.extent * r;
    return {
      t,
      o: [o[0] + s * sw.e2[0], o[1] + s * sw.e2[1], o[2] + s * sw.e2[2]],
      d: [d[0], d[1], d[2]],
      x: (sw.h0 + s) / r,
    };
  }
  const th = u * sw.extent * sw.alpha;
  const cs = Math.cos(th) * sw.dl;
  const sn = Math.sin(th) * sw.dl;
  return {
    t,
    o: [o[0], o[1], o[2]],
    d: [cs * sw.e1[0] + sn * sw.e2[0], cs * sw.e1[1] + sn * sw.e2[1], cs * sw.e1[2] + sn * sw.e2[2]],
    x: psi(sw, th),
  };
}

/** Angle between the direction at in-plane angle θ and the direction to C, in angular radii, in (−π/α, π/α]. */
function psi(sw: Sweep, theta: number): number {
  let p = theta - sw.omega;
  p = Math.atan2(Math.sin(p), Math.cos(p));
  return p / sw.alpha;
}

/** The sweep range of x (the Δ plot's axis), from t = 0 to t = 1 (may decrease). */
export function sweepXRange(sw: Sweep): [number, number] {
  return [sweepAt(sw, 0).x, sweepAt(sw, 1).x];
}

/** The scene's parameters with the ray moved to timeline position t (for computeModel). */
export function paramsAt(p: RaySphereParams, sw: Sweep, t: number): RaySphereParams {
  const s = sweepAt(sw, t);
  return { ...p, o: s.o, d: s.d };
}

export interface SweepSeries {
  t: number[];
  x: number[];
  /** Δ by each method at each sample (in the meaning b² − 4ac). */
  discNaive: number[];
  discStable: number[];
  /** The chosen method's case at each sample. */
  cases: RaySphereCase[];
  /** Positions t where the robust Δ changes sign (tangency), refined by bisection. */
  tangents: number[];
  /** Samples where the textbook Δ has the wrong sign (against the robust one, which is within its error bound). */
  naiveSignWrong: number;
  /** A fixed window for the g(t) plot over the whole sweep: t range (before the shift) and g range. */
  gWindow: { tMin: number; tMax: number; gMin: number; gMax: number; shift: number };
}

/**
 * Sample the sweep (n + 1 positions) for the Δ plot, the case strip and the g(t) plot's fixed
 * window. Pure; t-independent (memoise on the parameters).
 */
export function sweepSeries(p: Pick<RaySphereParams, 'method'>, sw: Sweep, n = 240): SweepSeries {
  const out: SweepSeries = {
    t: [],
    x: [],
    discNaive: [],
    discStable: [],
    cases: [],
    tangents: [],
    naiveSignWrong: 0,
    gWindow: { tMin: 0, tMax: 1, gMin: -1, gMax: 1, shift: 0 },
  };
  const { c, r } = sw.base;
  const method = p.method;
  let lo = Infinity;
  let hi = -Infinity;
  const tvs: number[] = [];
  const discs: number[] = [];
  let a = 1;
  for (let i = 0; i <= n; i++) {
    const t = i / n;
    const s = sweepAt(sw, t);
    const rn = intersectRaySphere(s.o, s.d, c, r, 'naive');
    const rs = intersectRaySphere(s.o, s.d, c, r, 'stable');
    if (!rn.ok || !rs.ok) continue;
    a = rs.a;
    out.t.push(t);
    out.x.push(s.x);
    out.discNaive.push(rn.discriminant);
    out.discStable.push(rs.discriminant);
    const ch = method === 'naive' ? rn : rs;
    out.cases.push(ch.case);
    if (Math.sign(rn.discriminant) !== Math.sign(rs.discriminant) && !rs.nearTangent) out.naiveSignWrong++;
    tvs.push(-ch.b / (2 * ch.a));
    discs.push(ch.discriminant);
    if (ch.t0 !== null) {
      lo = Math.min(lo, ch.t0);
      hi = Math.max(hi, ch.t1!);
    }
  }
  // tangency: sign changes of the robust Δ between samples, bisected to the last bit of t
  const sign = (t: number) => {
    const s = sweepAt(sw, t);
    const res = intersectRaySphere(s.o, s.d, c, r, 'stable');
    return res.ok ? Math.sign(res.discriminant) : 0;
  };
  for (let i = 1; i < out.t.length; i++) {
    const s0 = Math.sign(out.discStable[i - 1]);
    const s1 = Math.sign(out.discStable[i]);
    if (s0 === s1) continue;
    if (s1 === 0) {
      out.tangents.push(out.t[i]);
      continue;
    }
    if (s0 === 0) continue;
    let a0 = out.t[i - 1];
    let a1 = out.t[i];
    for (let k = 0; k < 60 && a1 - a0 > 1e-15; k++) {
      const m = 0.5 * (a0 + a1);
      const sm = sign(m);
      if (sm === 0) {
        a0 = a1 = m;
        break;
      }
      if (sm === s0) a0 = m;
      else a1 = m;
    }
    out.tangents.push(0.5 * (a0 + a1));
  }
  // g(t) window: every root of the sweep, and the vertex; t = 0 when it is not far off
  const tvMin = Math.min(...tvs);
  const tvMax = Math.max(...tvs);
  const spread = Number.isFinite(lo) ? hi - lo : 0;
  const discMax = Math.max(...discs.map(Math.abs));
  let half = Math.max(spread * 0.6, tvMax - tvMin, Math.sqrt(discMax) / a, 1e-300);
  if (!Number.isFinite(half) || half <= 0) half = 1;
  const mid = Number.isFinite(lo) ? 0.5 * (lo + hi) : 0.5 * (tvMin + tvMax);
  // a window narrower than the spacing of doubles near mid would collapse
  half = Math.max(half, Math.abs(mid) * 1e-12);
  let tMin = Math.min(mid - half, tvMin - 0.25 * half);
  let tMax = Math.max(mid + half, tvMax + 0.25 * half);
  if (Math.abs(mid) < 3 * half) {
    tMin = Math.min(tMin, -0.15 * half);
    tMax = Math.max(tMax, 0.15 * half);
  }
  const shift = Math.abs(mid) > 1e4 * (tMax - tMin) ? mid : 0;
  // g in vertex form a (t − t_v)² − Δ / 4a, over the window, for every sampled state
  let gMin = Infinity;
  let gMax = -Infinity;
  for (let i = 0; i < tvs.length; i++) {
    const tv = tvs[i];
    const k = discs[i] / (4 * a);
    const far = Math.max((tMin - tv) ** 2, (tMax - tv) ** 2);
    gMin = Math.min(gMin, -k);
    gMax = Math.max(gMax, a * far - k);
  }
  if (!(gMax > gMin)) {
    gMin -= 1;
    gMax += 1;
  }
  const pad = 0.08 * (gMax - gMin);
  out.gWindow = { tMin, tMax, gMin: Math.min(gMin - pad, -pad), gMax: gMax + pad, shift };
  return out;
}

// ---------------------------------------------------------------------------------------------
// Why renderers test t > t_min instead of t ≥ 0: a secondary ray that starts on the surface.

export interface SecondaryRay {
  /** The starting point, computed in doubles (so not exactly on the sphere). */
  p: V3;
  /** |p − C| − r: how far rounding has put p off the surface. */
  offSurface: number;
  /** The outward normal at p: the ray's direction (a light straight above the surface). */
  n: V3;
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
export function secondaryRay(q: V3, c: V3, r: number, method: RaySphereMethod): SecondaryRay | null {
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
  c: V3,
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
  c: V3,
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
    const u: V3 = [s * Math.cos(ph), s * Math.sin(ph), z];
    const sec = secondaryRay([c[0] + r * u[0], c[1] + r * u[1], c[2] + r * u[2]], c, r, method);
    if (!sec) continue;
    n++;
    if (sec.selfHit !== null) withZero++;
    if (sec.hitWithTMin !== null) withTMin++;
  }
  return { count: n, withZero, withTMin };
}
