/**
 * Model of #/area-light: pure functions of the URL parameters (no DOM, no React, no three).
 * Builds the light, the optional occluder and the shading point, validates them (bad input →
 * a message and a safe fallback), and computes everything the view shows by calling the core:
 * the analytic reference (Lambert's formula), the three estimators with standard errors, the
 * solid angle (and its closed form when one applies), the Q6(a) patch, convergence series, and
 * the progressive floor images (run in a worker, but the pixel kernel lives here).
 */
import {
  areaLightConvergence,
  areaLightTerms,
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
  makeSphericalRect,
  type AreaLightSetup,
  type LightStrategy,
  type RectLight,
  type Vec3,
} from '../../core/lights';
import {
  alignedRectangleSolidAngle,
  patchSolidAngleApprox,
  parallelogramSolidAngle,
} from '../../core/geometry/solidAngle';
import { logSpacedCounts } from '../../core/estimators/convergence';
import { Rng } from '../../core/random';
import { Welford } from '../../core/estimators/welford';
import { schema, type AreaLightParams } from './params';

export const STRATEGIES: readonly LightStrategy[] = ['area', 'solid-angle', 'cosine'];
export const STRATEGY_SHORT: Record<LightStrategy, string> = {
  area: 'area (key)',
  'solid-angle': 'solid angle',
  cosine: 'cosine',
};
export const STRATEGY_LABEL: Record<LightStrategy, string> = {
  area: 'uniform area (the key)',
  'solid-angle': 'solid angle (spherical rectangle)',
  cosine: 'cosine hemisphere',
};

/** A message about the current input: what is wrong (or notable) and what the scene does instead. */
export interface ModelMessage {
  kind: 'info' | 'warn' | 'error';
  text: string;
}

/** Everything derived from the parameters, before any sampling. */
export interface AreaLightModel {
  /** The parameters actually used (after fallbacks). */
  p: Vec3;
  lc: Vec3;
  w: number;
  h: number;
  tilt: number;
  L: number;
  rho: number;
  light: RectLight;
  occluder: RectLight | null;
  setup: AreaLightSetup;
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

/**
 * Validate the parameters and build the model. Bad input never throws: zero-size lights, a
 * shading point on the light, non-finite values are reported in `messages` and replaced by safe
 * values (the defaults).
 */
/** Smallest light area the model computes with: below it, w·h and the r²-scaled terms underflow. */
const MIN_AREA = 1e-200;

export function buildModel(params: AreaLightParams): AreaLightModel {
  const messages: ModelMessage[] = [];
  const def = schema;
  let p: Vec3 = finite3(params.p) ? [...params.p] : [...def.p.default];
  let lc: Vec3 = finite3(params.lc) ? [...params.lc] : [...def.lc.default];
  if (!finite3(params.p))
    messages.push({ kind: 'error', text: 'The shading point p is not three finite numbers; using 0,0,0.' });
  if (!finite3(params.lc))
    messages.push({ kind: 'error', text: 'The light centre is not three finite numbers; using 0,0,2.' });
  let w = params.ls?.[0] ?? NaN;
  let h = params.ls?.[1] ?? NaN;
  if (!(Number.isFinite(w) && Number.isFinite(h) && w > 0 && h > 0 && w * h >= MIN_AREA)) {
    messages.push({
      kind: 'error',
      text:
        w > 0 && h > 0 && Number.isFinite(w * h)
          ? `A light of size ${fmtSize(w)} × ${fmtSize(h)} has an area of ${w * h === 0 ? 'less than the smallest double (it rounds to 0)' : (w * h).toExponential(1)}, too small to compute with (below ${MIN_AREA}). Using 1 × 1 instead.`
          : `A light of size ${fmtSize(w)} × ${fmtSize(h)} has no area, so it emits nothing and has no solid angle to sample. Using 1 × 1 instead.`,
    });
    w = 1;
    h = 1;
  }
  let tilt = Number.isFinite(params.tilt) ? params.tilt : 0;
  const L = Number.isFinite(params.L) && params.L >= 0 ? params.L : 1;
  const rho = Number.isFinite(params.rho) && params.rho >= 0 && params.rho <= 1 ? params.rho : 0.8;
  let light = makeRectLight(lc, w, h, tilt);
  if (onLight(light, p)) {
    messages.push({
      kind: 'error',
      text: 'The shading point lies on the light itself: r = 0 there and the integrand is singular. Moving the point to 0,0,0 (and the light to 0,0,2 if needed).',
    });
    p = [0, 0, 0];
    if (onLight(light, p)) {
      lc = [0, 0, 2];
      tilt = 0;
      light = makeRectLight(lc, w, h, tilt);
    }
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
    messages.push({
      kind: 'info',
      text:
        dist === 0
          ? 'The point lies in the light’s plane: the light is seen edge-on, Ω = 0 and L_o = 0.'
          : 'The light faces away from the point (its back is black): L_o = 0, and every estimator returns exactly 0.',
    });
  } else if (belowHorizon >= 1) {
    messages.push({
      kind: 'info',
      text: 'The whole light is below the floor’s horizon: cos θ ≤ 0 everywhere, so L_o = 0.',
    });
  } else if (belowHorizon > 0) {
    messages.push({
      kind: 'info',
      text: `${Math.round(belowHorizon * 100)}% of the light is below the horizon: Lambert’s formula uses the light clipped to z ≥ ${p[2]}, and the estimators give those samples weight 0.`,
    });
  }
  if (occluder && referenceOccluded !== null && !Number.isFinite(referenceOccluded)) {
    messages.push({
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
    messages,
    reference,
    referenceOccluded,
    solidAngle,
    solidAngleClosed,
    projectedSolidAngle: projected,
    facing,
    belowHorizon,
  };
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

/** Fraction of the light's area with z < zFloor (the part below the shading point's horizon). */
export function fractionBelow(light: RectLight, zFloor: number): number {
  // z is affine over the rectangle: z(a, b) = s_z + a e_x,z + b e_y,z on [0,1]²; integrate the
  // indicator numerically on a fine grid (exact enough for a notice).
  const K = 64;
  let below = 0;
  for (let i = 0; i < K; i++)
    for (let j = 0; j < K; j++) {
      const z = light.corner[2] + ((i + 0.5) / K) * light.edgeX[2] + ((j + 0.5) / K) * light.edgeY[2];
      if (z < zFloor) below++;
    }
  return below / (K * K);
}

/**
 * The optional occluder: a horizontal rectangle 0.4 w × 0.4 h centred halfway between p and the
 * light centre (so it shadows the middle of the light as seen from p).
 */
export function makeOccluder(p: Vec3, lc: Vec3, w: number, h: number): RectLight {
  return makeRectLight([(p[0] + lc[0]) / 2, (p[1] + lc[1]) / 2, (p[2] + lc[2]) / 2], 0.4 * w, 0.4 * h, 0);
}

/** One strategy's estimate of L_o with its standard error. */
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

/**
 * Samples to draw: for each strategy, up to `count` samples (points on the light for the light
 * strategies, unit directions for cosine) and their estimator terms. Same streams as
 * {@link estimateAll}, so the drawn samples are the first ones of the estimate.
 */
export function drawSamples(
  m: AreaLightModel,
  strategy: LightStrategy,
  count: number,
  seed: number,
): { points: Float64Array; terms: Float64Array } {
  const u = new Float64Array(2 * count);
  new Rng(seed, STRATEGIES.indexOf(strategy)).fill(u);
  const points = new Float64Array(3 * count);
  const terms = new Float64Array(count);
  areaLightTerms(m.setup, strategy, u, count, terms, points);
  return { points, terms };
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

// ---------------------------------------------------------------------------------------------
// Q6(a): a small patch on the light, its exact solid angle and dA cos θ_l / r².

export interface PatchModel {
  /** Patch corners (world), counter-clockwise. */
  corners: Vec3[];
  centre: Vec3;
  /** Unit normal of the patch (emitting side of the light, tilted by ptilt). */
  normal: Vec3;
  side: number;
  area: number;
  r: number;
  cosThetaL: number;
  exact: number;
  approx: number;
  /** (approx − exact)/exact. */
  relError: number;
  /** Corners projected onto the unit sphere around p (world positions). */
  projected: Vec3[];
  /** Relative error against side length as the patch shrinks (for the plot). */
  series: { side: Float64Array; relError: Float64Array };
}

/** A square patch of side s at (pu, pv) on the light, tilted by ptilt about the light's x axis. */
export function patchGeometry(m: AreaLightModel, pu: number, pv: number, side: number, ptilt: number) {
  const l = m.light;
  const centre: Vec3 = [0, 1, 2].map((k) => l.corner[k] + pu * l.edgeX[k] + pv * l.edgeY[k]) as Vec3;
  const patch = makeRectLight(centre, side, side, m.tilt + ptilt);
  return patch;
}

export function patchModel(
  m: AreaLightModel,
  pu: number,
  pv: number,
  side: number,
  ptilt: number,
): PatchModel {
  const patch = patchGeometry(m, pu, pv, side, ptilt);
  const [px, py, pz] = m.p;
  const c = patch.center;
  const measure = (pt: RectLight) => {
    const dx = pt.center[0] - px,
      dy = pt.center[1] - py,
      dz = pt.center[2] - pz;
    const r = Math.hypot(dx, dy, dz);
    const cosL = r > 0 ? Math.abs(dx * pt.normal[0] + dy * pt.normal[1] + dz * pt.normal[2]) / r : 0;
    const exact = parallelogramSolidAngle(
      pt.corner[0] - px,
      pt.corner[1] - py,
      pt.corner[2] - pz,
      ...pt.edgeX,
      ...pt.edgeY,
    );
    const approx = patchSolidAngleApprox(pt.area, cosL, r);
    return { r, cosL, exact, approx, rel: exact > 0 ? (approx - exact) / exact : NaN };
  };
  const cur = measure(patch);
  const projected = patch.corners.map((q) => {
    const d = [q[0] - px, q[1] - py, q[2] - pz];
    const len = Math.hypot(d[0], d[1], d[2]) || 1;
    return [px + d[0] / len, py + d[1] / len, pz + d[2] / len] as Vec3;
  });
  const K = 25;
  const sides = new Float64Array(K);
  const rels = new Float64Array(K);
  const sMax = Math.max(side, 1);
  for (let i = 0; i < K; i++) {
    const s = sMax * 10 ** (-(5 * i) / (K - 1));
    sides[i] = s;
    const r = measure(makeRectLight(c, s, s, m.tilt + ptilt)).rel;
    rels[i] = Number.isFinite(r) ? Math.abs(r) : NaN;
  }
  return {
    corners: patch.corners,
    centre: c,
    normal: patch.normal,
    side,
    area: patch.area,
    r: cur.r,
    cosThetaL: cur.cosL,
    exact: cur.exact,
    approx: cur.approx,
    relError: cur.rel,
    projected,
    series: { side: sides, relError: rels },
  };
}

// ---------------------------------------------------------------------------------------------
// Progressive floor images (the worker runs these; pure functions of plain data).

/** Plain-data description of the scene for the worker (structured-clonable). */
export interface FloorJob {
  lc: Vec3;
  w: number;
  h: number;
  tilt: number;
  L: number;
  rho: number;
  occluder: boolean;
  p: Vec3;
  /** Image side in pixels and the floor square it covers: [cx − half, cx + half]², z = p.z. */
  size: number;
  cx: number;
  cy: number;
  half: number;
  seed: number;
}

/** The floor square shown by the images: centred under the light's footprint, covering the point. */
export function floorJob(m: AreaLightModel, seed: number, size = 72): FloorJob {
  const cx = (m.p[0] + m.lc[0]) / 2,
    cy = (m.p[1] + m.lc[1]) / 2;
  const reach = Math.hypot(m.lc[0] - m.p[0], m.lc[1] - m.p[1]) / 2 + Math.max(m.w, m.h) / 2;
  const half = Math.min(1e6, Math.max(1.5, reach * 1.3, Math.abs(m.lc[2] - m.p[2]) * 0.9));
  return {
    lc: m.lc,
    w: m.w,
    h: m.h,
    tilt: m.tilt,
    L: m.L,
    rho: m.rho,
    occluder: !!m.occluder,
    p: m.p,
    size,
    cx,
    cy,
    half,
    seed,
  };
}

/** World position of pixel (i, j) centre (row j from the top = +y side). */
export function pixelPoint(job: FloorJob, i: number, j: number): [number, number] {
  const s = (2 * job.half) / job.size;
  return [job.cx - job.half + (i + 0.5) * s, job.cy + job.half - (j + 0.5) * s];
}

/** The reference image: analytic L_o per pixel (unoccluded, or occluded where it has a closed form). */
export function referenceImage(job: FloorJob): Float32Array {
  const light = makeRectLight(job.lc, job.w, job.h, job.tilt);
  const img = new Float32Array(job.size * job.size);
  const z = job.p[2];
  for (let j = 0; j < job.size; j++)
    for (let i = 0; i < job.size; i++) {
      const [x, y] = pixelPoint(job, i, j);
      let v = lambertianFloorRadiance(light, x, y, z, job.L, job.rho);
      if (job.occluder) {
        const occ = makeOccluder(job.p, job.lc, job.w, job.h);
        const ps = rectProjectedSolidAngleOccluded(light, occ, x, y, z);
        v = Number.isFinite(ps) ? (job.rho / Math.PI) * job.L * ps : NaN;
      }
      img[j * job.size + i] = v;
    }
  return img;
}

/**
 * One progressive pass: add `spp` samples of `strategy` to every pixel's running sum (sum is
 * caller-owned, length size²). Pass index k selects the random stream, so passes are independent.
 */
export function floorPass(
  job: FloorJob,
  strategy: LightStrategy,
  spp: number,
  pass: number,
  sum: Float64Array,
): void {
  const light = makeRectLight(job.lc, job.w, job.h, job.tilt);
  const occ = job.occluder ? makeOccluder(job.p, job.lc, job.w, job.h) : null;
  const rng = new Rng(job.seed, 1000 + pass * 3 + STRATEGIES.indexOf(strategy));
  const u = new Float64Array(2 * spp);
  const terms = new Float64Array(spp);
  const setup: AreaLightSetup = { light, occluder: occ, px: 0, py: 0, pz: job.p[2], L: job.L, rho: job.rho };
  for (let j = 0; j < job.size; j++)
    for (let i = 0; i < job.size; i++) {
      const [x, y] = pixelPoint(job, i, j);
      setup.px = x;
      setup.py = y;
      rng.fill(u);
      const sph = strategy === 'solid-angle' ? makeSphericalRect(light, x, y, job.p[2]) : undefined;
      areaLightTerms(setup, strategy, u, spp, terms, undefined, sph);
      let s = 0;
      for (let k = 0; k < spp; k++) s += terms[k];
      sum[j * job.size + i] += s;
    }
}

/** RMSE of an image (sum / spp) against the reference, over pixels where the reference is finite. */
export function imageRmse(sum: Float64Array, spp: number, ref: Float32Array): number {
  let s = 0,
    n = 0;
  for (let k = 0; k < ref.length; k++) {
    const r = ref[k];
    if (!Number.isFinite(r)) continue;
    const d = sum[k] / spp - r;
    s += d * d;
    n++;
  }
  return n ? Math.sqrt(s / n) : NaN;
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

// ---------------------------------------------------------------------------------------------
// The animation (issue 12): samples of the chosen strategy arrive one by one; position t on the
// shared timeline = the number of samples that have arrived. Everything shown at t is a function
// of (params, seed, t) computed here.

/** Most samples the animation shows (the timeline runs 0 … min(n, ANIM_MAX)). */
export const ANIM_MAX = 1024;

/** Length of the timeline for n samples. */
export function animationLength(n: number): number {
  return Math.max(1, Math.min(ANIM_MAX, Math.floor(n) || 1));
}

/** The samples of one strategy with the running estimate and standard error after each. */
export interface SampleRun {
  strategy: LightStrategy;
  count: number;
  points: Float64Array;
  terms: Float64Array;
  /** mean[i] = estimate after i + 1 samples. */
  mean: Float64Array;
  /** stderr[i] = s/√(i+1) after i + 1 samples (NaN for one sample). */
  stderr: Float64Array;
}

/** The first `count` samples of `strategy` (the estimate's own stream) and their running statistics (core Welford). */
export function sampleRun(
  m: AreaLightModel,
  strategy: LightStrategy,
  count: number,
  seed: number,
): SampleRun {
  const { points, terms } = drawSamples(m, strategy, count, seed);
  const mean = new Float64Array(count);
  const stderr = new Float64Array(count);
  const w = new Welford();
  for (let i = 0; i < count; i++) {
    w.add(terms[i]);
    mean[i] = w.mean;
    stderr[i] = w.standardError();
  }
  return { strategy, count, points, terms, mean, stderr };
}

/** What the animation shows at position t. */
export interface AnimationFrame {
  /** Samples arrived: floor(t) clamped to [0, count]. */
  k: number;
  /** Running estimate after k samples (NaN for k = 0). */
  estimate: number;
  /** Its standard error (NaN for k < 2). */
  stderr: number;
  /** Index of the newest sample (k − 1), or −1. */
  newest: number;
  /** The newest sample's term (NaN for k = 0). */
  newestTerm: number;
}

export function animationFrame(run: SampleRun, t: number): AnimationFrame {
  const k = Math.max(0, Math.min(run.count, Math.floor(Number.isFinite(t) ? t + 1e-9 : 0)));
  return {
    k,
    estimate: k > 0 ? run.mean[k - 1] : NaN,
    stderr: k > 1 ? run.stderr[k - 1] : NaN,
    newest: k - 1,
    newestTerm: k > 0 ? run.terms[k - 1] : NaN,
  };
}

/** Samples per pixel added by each progressive pass of the floor images: 1, 1, 2, 4, … (the total doubles). */
export const PASS_SPP = [1, 1, 2, 4, 8, 16, 32] as const;
/** Total samples per pixel after each pass: 1, 2, 4, …, 64. */
export const PASS_TOTAL: readonly number[] = PASS_SPP.map((_, i) =>
  PASS_SPP.slice(0, i + 1).reduce((a, b) => a + b, 0),
);

/**
 * The floor images refine in step with the timeline: at position t of max, show the pass whose
 * samples per pixel are the largest not above the same fraction of the full 64 (at least pass 0).
 */
export function floorPassAt(t: number, max: number): number {
  const total = PASS_TOTAL[PASS_TOTAL.length - 1];
  const want = max > 0 ? (total * Math.max(0, Math.min(max, t))) / max : total;
  let k = 0;
  for (let i = 0; i < PASS_TOTAL.length; i++) if (PASS_TOTAL[i] <= want + 1e-9) k = i;
  return k;
}
