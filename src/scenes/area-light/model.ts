/**
 * Model of #/area-light: pure functions of the URL parameters (no DOM, no React, no three).
 * Builds the light, the optional occluder and the shading point, validates them (bad input → a
 * refusal and a safe fallback), and computes what the view shows by calling the core: the analytic
 * reference (Lambert's formula), the three estimators with standard errors, the solid angle (and
 * its closed form when one applies), convergence series, the run-time study and Q6(c)'s first
 * samples. The Q6(a) patch is in ./patch, the animation in ./animation, the floor images in
 * ./floor.
 */
import {
  areaLightConvergence,
  areaToSolidAnglePdf,
  intersectRect,
  rectAreaPdf,
  sampleRectArea,
  estimateAreaLight,
  lambertianFloorRadiance,
  makeRectLight,
  rectFacesPoint,
  rectPlaneDistance,
  rectProjectedSolidAngle,
  rectProjectedSolidAngleOccluded,
  rectSolidAngle,
  type AreaLightSetup,
  type LightStrategy,
  type RectLight,
  type Vec3,
} from '../../core/lights';
import { sameVec } from '../../core/vec3';
import { alignedRectangleSolidAngle } from '../../core/geometry/solidAngle';
import { logSpacedCounts } from '../../core/estimators/convergence';
import { Rng } from '../../core/random';
import { fail, type Failure } from '../../core/failure';
import type { ParamProblem } from '../../kit/params';
import { schema, type AreaLightParams } from './params';
import { STRATEGIES } from './strategies';

/**
 * An input the model refused and replaced by a safe value: `kind` names the input, `message`
 * says what is wrong and what the scene uses instead.
 */
export type Refusal = Failure<'bad-point' | 'bad-centre' | 'no-area' | 'tiny-area' | 'point-on-light'>;

/** A message about the current input: what is wrong (or notable) and what the scene does instead. */
export interface ModelMessage {
  kind: 'info' | 'warn' | 'error';
  text: string;
}

/** The light and floor as used (after fallbacks): what the floor images need besides the point. */
export interface LightInputs {
  p: Vec3;
  lc: Vec3;
  w: number;
  h: number;
  tilt: number;
  L: number;
  rho: number;
}

/** Everything derived from the parameters, before any sampling. */
export interface AreaLightModel extends LightInputs {
  light: RectLight;
  occluder: RectLight | null;
  setup: AreaLightSetup;
  /** The inputs refused and replaced by safe values, in the order of the checks. */
  refusals: Refusal[];
  /**
   * Each parameter whose value the model does not use as given, once, with why (the refusal's
   * message, or what replaced a radiance, albedo or tilt it cannot use), in schema order.
   */
  problems: ParamProblem[];
  /** What the page shows: the refusals (as errors), then remarks about the input (info). */
  messages: ModelMessage[];
  /** Analytic L_o without the occluder (the contract's `reference`). */
  reference: number;
  /** Analytic L_o with the occluder (NaN when no closed form applies; null when no occluder). */
  referenceOccluded: number | null;
  /** Ω of the light seen from p (Van Oosterom–Strackee). */
  solidAngle: number;
  /** Ω by the aligned-rectangle closed form (light parallel to the floor), else null. */
  solidAngleClosed: number | null;
  /** ∫ cos θ dω over the light (projected solid angle, clipped to the horizon). */
  projectedSolidAngle: number;
  facing: boolean;
  /** Fraction of the light's area below the floor's horizon (z < p.z), for the notices. */
  belowHorizon: number;
}

const finite3 = (v: readonly number[]) => v.length === 3 && v.every(Number.isFinite);

/** Tolerance for "the point lies on the light": distance to the plane below this × scale. */
const ON_LIGHT_EPS = 1e-9;

/** Smallest light area the model computes with: below it, w·h and the r²-scaled terms underflow. */
const MIN_AREA = 1e-200;

/** The refusal of a light of size w × h that has no usable area. */
function sizeRefusal(w: number, h: number): Refusal {
  const size = `A light of size ${fmtSize(w)} × ${fmtSize(h)}`;
  if (!(w > 0 && h > 0 && Number.isFinite(w * h)))
    return fail(
      'no-area',
      `${size} has no area, so it emits nothing and has no solid angle to sample. Using 1 × 1 instead.`,
    );
  const area = w * h === 0 ? 'less than the smallest double (it rounds to 0)' : (w * h).toExponential(1);
  return fail(
    'tiny-area',
    `${size} has an area of ${area}, too small to compute with (below ${MIN_AREA}). Using 1 × 1 instead.`,
  );
}

/**
 * Validate the parameters and build the model. Bad input never throws: zero-size lights, a
 * shading point on the light, non-finite values are refused (in `refusals`, shown in `messages`)
 * and replaced by safe values (the defaults).
 */
export function buildModel(params: AreaLightParams): AreaLightModel {
  const refusals: Refusal[] = [];
  const problems: ParamProblem[] = [];
  const refuse = (names: readonly (keyof AreaLightParams)[], f: Refusal) => {
    refusals.push(f);
    for (const name of names) problems.push({ name, message: f.message });
  };
  const notes: ModelMessage[] = [];
  const def = schema;
  let p: Vec3 = finite3(params.p) ? [...params.p] : [...def.p.default];
  let lc: Vec3 = finite3(params.lc) ? [...params.lc] : [...def.lc.default];
  if (!finite3(params.p))
    refuse(['p'], fail('bad-point', 'The shading point p is not three finite numbers; using 0,0,0.'));
  if (!finite3(params.lc))
    refuse(
      ['lc'],
      fail('bad-centre', `The light centre is not three finite numbers; using ${def.lc.default.join(',')}.`),
    );
  let w = params.ls?.[0] ?? NaN;
  let h = params.ls?.[1] ?? NaN;
  if (!(Number.isFinite(w) && Number.isFinite(h) && w > 0 && h > 0 && w * h >= MIN_AREA)) {
    refuse(['ls'], sizeRefusal(w, h));
    w = 1;
    h = 1;
  }
  let tilt = Number.isFinite(params.tilt) ? params.tilt : 0;
  if (!Number.isFinite(params.tilt))
    problems.push({ name: 'tilt', message: 'The light’s tilt is not a finite number; using 0.' });
  const L = Number.isFinite(params.L) && params.L >= 0 ? params.L : 1;
  if (L !== params.L)
    problems.push({ name: 'L', message: 'The radiance L must be a finite number ≥ 0; using 1.' });
  const rho = Number.isFinite(params.rho) && params.rho >= 0 && params.rho <= 1 ? params.rho : 0.8;
  if (rho !== params.rho)
    problems.push({ name: 'rho', message: 'The albedo ρ must be a number from 0 to 1; using 0.8.' });
  let light = makeRectLight(lc, w, h, tilt);
  if (onLight(light, p)) {
    const moved: (keyof AreaLightParams)[] = sameVec(p, [0, 0, 0]) ? [] : ['p'];
    p = [0, 0, 0];
    if (onLight(light, p)) {
      if (!sameVec(lc, [0, 0, 2])) moved.push('lc');
      if (tilt !== 0) moved.push('tilt');
      lc = [0, 0, 2];
      tilt = 0;
      light = makeRectLight(lc, w, h, tilt);
    }
    refuse(
      moved,
      fail(
        'point-on-light',
        'The shading point lies on the light itself: r = 0 there and the integrand is singular. ' +
          'Moving the point to 0,0,0 (and the light to 0,0,2 if needed).',
      ),
    );
  }
  const occluder = params.occluder ? makeOccluder(p, lc, w, h) : null;
  const setup: AreaLightSetup = { light, occluder, px: p[0], py: p[1], pz: p[2], L, rho };
  const facing = rectFacesPoint(light, p[0], p[1], p[2]);
  const reference = lambertianFloorRadiance(light, p[0], p[1], p[2], L, rho);
  const projected = rectProjectedSolidAngle(light, p[0], p[1], p[2]);
  let referenceOccluded: number | null = null;
  if (occluder) {
    const ps = rectProjectedSolidAngleOccluded(light, occluder, p[0], p[1], p[2]);
    referenceOccluded = Number.isFinite(ps) ? (rho / Math.PI) * L * ps : NaN;
  }
  const solidAngle = rectSolidAngle(light, p[0], p[1], p[2]);
  let solidAngleClosed: number | null = null;
  const tmod = ((tilt % 180) + 180) % 180;
  if (tmod === 0) {
    // Light parallel to the floor: coordinates in its plane relative to the foot of p.
    const d = lc[2] - p[2];
    const x0 = lc[0] - w / 2 - p[0],
      x1 = lc[0] + w / 2 - p[0];
    const y0 = lc[1] - h / 2 - p[1],
      y1 = lc[1] + h / 2 - p[1];
    solidAngleClosed = d !== 0 ? alignedRectangleSolidAngle(x0, x1, y0, y1, d) : 0;
  }
  const belowHorizon = fractionBelow(light, p[2]);
  if (!facing) {
    const dist = rectPlaneDistance(light, p[0], p[1], p[2]);
    notes.push({
      kind: 'info',
      text:
        dist === 0
          ? 'The point lies in the light’s plane: the light is seen edge-on, Ω = 0 and L_o = 0.'
          : 'The light faces away from the point (its back is black): L_o = 0, and every estimator returns exactly 0.',
    });
  } else if (belowHorizon >= 1) {
    notes.push({
      kind: 'info',
      text: 'The whole light is below the floor’s horizon: cos θ ≤ 0 everywhere, so L_o = 0.',
    });
  } else if (belowHorizon > 0) {
    notes.push({
      kind: 'info',
      text: `${percentOfPart(belowHorizon)} of the light is below the horizon: Lambert’s formula uses the light clipped to z ≥ ${p[2]}, and the estimators give those samples weight 0.`,
    });
  }
  if (occluder && referenceOccluded !== null && !Number.isFinite(referenceOccluded)) {
    notes.push({
      kind: 'info',
      text: 'The occluder is not wholly between the point and the light, so no analytic occluded value is shown.',
    });
  }
  return {
    p,
    lc,
    w,
    h,
    tilt,
    L,
    rho,
    light,
    occluder,
    setup,
    refusals,
    problems: inSchemaOrder(problems),
    messages: [...refusals.map((f): ModelMessage => ({ kind: 'error', text: f.message })), ...notes],
    reference,
    referenceOccluded,
    solidAngle,
    solidAngleClosed,
    projectedSolidAngle: projected,
    facing,
    belowHorizon,
  };
}

/** The problems in the schema's order of parameters, the first one of each parameter only. */
function inSchemaOrder(problems: ParamProblem[]): ParamProblem[] {
  const names = Object.keys(schema);
  return names.flatMap((name) => problems.find((x) => x.name === name) ?? []);
}

function fmtSize(x: number): string {
  return Number.isFinite(x) ? String(x) : '?';
}

/** True when p lies on the light's rectangle (in its plane, within its edges). */
export function onLight(light: RectLight, p: readonly number[]): boolean {
  if (!(light.area > 0)) return false;
  const scale = Math.max(1, Math.hypot(...light.center), Math.hypot(p[0], p[1], p[2]));
  if (Math.abs(rectPlaneDistance(light, p[0], p[1], p[2])) > ON_LIGHT_EPS * scale) return false;
  const d = [p[0] - light.corner[0], p[1] - light.corner[1], p[2] - light.corner[2]];
  const a = d[0] * light.ex[0] + d[1] * light.ex[1] + d[2] * light.ex[2];
  const b = d[0] * light.ey[0] + d[1] * light.ey[1] + d[2] * light.ey[2];
  return a >= 0 && a <= light.width && b >= 0 && b <= light.height;
}

/**
 * The area of the part of the unit square [0, 1]² where a·p + b·q < c: the square clipped by a
 * half-plane (Sutherland–Hodgman against one edge), measured by the shoelace formula. Exact up to
 * rounding; 1 or 0 when p = q = 0, as c > 0 or not.
 */
export function squareAreaBelow(p: number, q: number, c: number): number {
  const square: [number, number][] = [
    [0, 0],
    [1, 0],
    [1, 1],
    [0, 1],
  ];
  // g > 0 inside the half-plane
  const g = ([a, b]: [number, number]) => c - (a * p + b * q);
  const poly: [number, number][] = [];
  for (let k = 0; k < 4; k++) {
    const A = square[k];
    const B = square[(k + 1) % 4];
    const ga = g(A);
    const gb = g(B);
    if (ga > 0) poly.push(A);
    if (ga > 0 !== gb > 0) {
      const t = ga / (ga - gb);
      poly.push([A[0] + t * (B[0] - A[0]), A[1] + t * (B[1] - A[1])]);
    }
  }
  let twice = 0;
  for (let k = 0; k < poly.length; k++) {
    const [x0, y0] = poly[k];
    const [x1, y1] = poly[(k + 1) % poly.length];
    twice += x0 * y1 - x1 * y0;
  }
  return Math.min(1, Math.max(0, twice / 2));
}

/**
 * Fraction of the light's area with z < zFloor (the part below the shading point's horizon): z is
 * affine over the rectangle, z(a, b) = s_z + a e_x,z + b e_y,z on [0, 1]², so the part below is the
 * unit square cut by a straight line ({@link squareAreaBelow}).
 */
export function fractionBelow(light: RectLight, zFloor: number): number {
  return squareAreaBelow(light.edgeX[2], light.edgeY[2], zFloor - light.corner[2]);
}

/** A fraction in (0, 1) as a whole percentage that never reads 0 % or 100 %. */
export function percentOfPart(f: number): string {
  const pct = 100 * f;
  if (pct < 0.5) return 'Less than 1%';
  if (pct >= 99.5) return 'Over 99%';
  return `${Math.round(pct)}%`;
}

/**
 * The optional occluder: a horizontal rectangle 0.4 w × 0.4 h centred halfway between p and the
 * light centre (so it shadows the middle of the light as seen from p).
 */
export function makeOccluder(p: Vec3, lc: Vec3, w: number, h: number): RectLight {
  return makeRectLight([(p[0] + lc[0]) / 2, (p[1] + lc[1]) / 2, (p[2] + lc[2]) / 2], 0.4 * w, 0.4 * h, 0);
}

/** One strategy's estimate of L_o with its standard error. */
/** Largest n per strategy estimated on the main thread (above it, in the scene's worker). */
export const SYNC_MAX = 65536;

export interface StrategyEstimate {
  strategy: LightStrategy;
  estimate: number;
  stderr: number;
  n: number;
}

/** One strategy with n samples (stream = the strategy's index in STRATEGIES: the numbers of estimateAll). */
export function estimateOne(
  m: AreaLightModel,
  strategy: LightStrategy,
  n: number,
  seed: number,
): StrategyEstimate {
  const r = estimateAreaLight(m.setup, strategy, n, seed, STRATEGIES.indexOf(strategy));
  return { strategy, estimate: r.estimate, stderr: r.stderr, n: r.n };
}

/** All three strategies with n samples each (streams 0, 1, 2 of the seed). */
export function estimateAll(m: AreaLightModel, n: number, seed: number): StrategyEstimate[] {
  return STRATEGIES.map((s) => estimateOne(m, s, n, seed));
}

/** The value the estimators converge to: the occluded reference when an occluder is on and known. */
export function targetValue(m: AreaLightModel): number {
  if (m.occluder)
    return m.referenceOccluded !== null && Number.isFinite(m.referenceOccluded) ? m.referenceOccluded : NaN;
  return m.reference;
}

/** Convergence series of the three strategies up to nMax (log-spaced checkpoints). */
export function convergence(m: AreaLightModel, nMax: number, seed: number) {
  const cps = logSpacedCounts(nMax, 8, 2);
  const exact = targetValue(m);
  return STRATEGIES.map((s, i) => {
    const c = areaLightConvergence(m.setup, s, cps, exact, seed, 16 + i);
    return { strategy: s, n: c.n, estimate: c.estimate, absError: c.absError, stderr: c.stderr };
  });
}

/** Seconds per sample from a timing run; kept here so the worker and the tests share it. */
export interface TimingPoint {
  strategy: LightStrategy;
  n: number;
  rmse: number;
  seconds: number;
}

/** Sample counts of the run-time-vs-error study. */
export const TIMING_COUNTS = [16, 64, 256, 1024, 4096] as const;
/** Independent runs per count for the RMSE. */
export const TIMING_RUNS = 24;

/** RMSE of `runs` independent estimates with n samples each against the target value. */
export function rmseOfRuns(
  m: AreaLightModel,
  strategy: LightStrategy,
  n: number,
  runs: number,
  seed: number,
): number {
  const target = targetValue(m);
  let s = 0;
  for (let r = 0; r < runs; r++) {
    const e = estimateAreaLight(
      m.setup,
      strategy,
      n,
      seed,
      100 + r * 3 + STRATEGIES.indexOf(strategy),
    ).estimate;
    s += (e - target) ** 2;
  }
  return Math.sqrt(s / runs);
}

// ---------------------------------------------------------------------------------------------
// Q6(c) with numbers: the first few samples of the key's estimator, term by term.

/** One sample of uniform area sampling, every factor of the key's estimator term. */
export interface GivenSample {
  u1: number;
  u2: number;
  /** The point on the light. */
  x: Vec3;
  r: number;
  cosTheta: number;
  cosThetaL: number;
  /** Visibility: 1, or 0 when the occluder blocks the segment (or the sample faces away / is below the horizon). */
  V: number;
  /** p_A (per unit area). */
  pA: number;
  /** f L V cos θ cos θ_l / (r² p_A) — the estimator's term. */
  term: number;
}

/**
 * The first `k` samples of the area strategy for this seed (the same stream as the estimate, so
 * they are its first terms), each factor computed with the core's sample/pdf pair, and their mean
 * ⟨L_o⟩ = (|A|/k) Σ f L V cos θ cos θ_l / r².
 */
export function givenSamples(
  m: AreaLightModel,
  seed: number,
  k = 4,
): { samples: GivenSample[]; f: number; area: number; estimate: number } {
  const u = new Float64Array(2 * k);
  new Rng(seed, STRATEGIES.indexOf('area')).fill(u);
  const f = m.rho / Math.PI;
  const [px, py, pz] = m.p;
  const nl = m.light.normal;
  const out: GivenSample[] = [];
  const x = [0, 0, 0];
  let sum = 0;
  for (let i = 0; i < k; i++) {
    sampleRectArea(m.light, u[2 * i], u[2 * i + 1], x);
    const dx = x[0] - px,
      dy = x[1] - py,
      dz = x[2] - pz;
    const r2 = dx * dx + dy * dy + dz * dz;
    const r = Math.sqrt(r2);
    const cosTheta = r > 0 ? dz / r : 0;
    const cosThetaL = r > 0 ? -(dx * nl[0] + dy * nl[1] + dz * nl[2]) / r : 0;
    const blocked = !!m.occluder && intersectRect(m.occluder, px, py, pz, dx, dy, dz, 0) < 1 - 1e-9;
    const V = cosTheta > 0 && cosThetaL > 0 && !blocked ? 1 : 0;
    const pA = rectAreaPdf(m.light, x[0], x[1], x[2]);
    const pw = areaToSolidAnglePdf(pA, r2, cosThetaL);
    const term = V && pw > 0 ? (f * m.L * cosTheta) / pw : 0;
    sum += term;
    out.push({ u1: u[2 * i], u2: u[2 * i + 1], x: [x[0], x[1], x[2]], r, cosTheta, cosThetaL, V, pA, term });
  }
  return { samples: out, f, area: m.light.area, estimate: k ? sum / k : NaN };
}
