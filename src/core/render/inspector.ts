/**
 * The pixel inspector: everything behind one pixel, as numbers. For pixel (i, j) (column i, row j
 * from the top left) the ray through its centre; the sphere's quadratic along it (discriminant
 * and t by the stable form, core/geometry/raySphere); what the ray hits and where; on the sphere
 * the exam's spherical (u, v) and the texture lookup; then the estimator of the radiance leaving
 * that point towards the eye with the chosen strategy: its first samples in full, its running
 * estimate and standard error after n samples, and the reference (exact where reference.ts has a
 * closed form, else a long run of the MIS estimator with its own standard error).
 */
import { intersectRaySphere } from '../geometry/raySphere';
import { Welford } from '../estimators/welford';
import { Rng } from '../random/rng';
import type { Vec3 } from '../vec3';
import { cameraRay, makeCamera } from './camera';
import type { Strategy } from './directLight';
import { newDirectSample, type DirectSample, type Technique } from './directSample';
import { closestHit, newHit, type HitKind } from './intersect';
import { newVertex, shadeVertex, type Vertex } from './material';
import { makeTracer, pathFromVertex, type TraceOptions } from './pathTrace';
import { exactRadiance } from './reference';
import { studentTTest, welchTTest, type TTestResult } from '../verify/ttest';
import type { RenderScene, View } from './scene';

/** Default number of samples of the inspector's estimate, of rows shown, and the reference's multiple. */
export const DEFAULT_PN = 4096;
export const DEFAULT_ROWS = 8;
export const CONVERGED_FACTOR = 16;

/** One sample of the direct-light estimator at the inspected point, as a row of the table. */
export interface SampleRow {
  technique: Technique;
  direction: Vec3;
  /** The point reached on a light (null: none, or the environment). */
  lightPoint: Vec3 | null;
  f: number;
  L: number;
  cosTheta: number;
  cosThetaL: number | null;
  r2: number | null;
  pdf: number;
  measure: 'solid-angle' | 'area';
  pdfSolidAngle: number;
  weight: number;
  term: number;
}

export interface PixelInspection {
  i: number;
  j: number;
  o: Vec3;
  d: Vec3;
  /** The sphere's quadratic along the ray (null without a sphere, t null on a miss). */
  discriminant: number | null;
  t: number | null;
  hit: HitKind;
  /** The hit point (null on a miss). */
  p: Vec3 | null;
  /** On the textured sphere: (u, v), the looked-up value and the albedo it gives (else null). */
  u: number | null;
  v: number | null;
  texel: number | null;
  albedo: number | null;
  rows: SampleRow[];
  estimate: number;
  stderr: number;
  n: number;
  reference: number;
  referenceKind: 'exact' | 'converged';
  referenceStderr: number;
  /**
   * The estimate tested against the reference at TTEST_ALPHA: Student's t-test against an exact
   * value, Welch's against a converged one (its own run, with its own variance); null where the
   * pixel has nothing to estimate (the sky, a light).
   */
  tTest: TTestResult | null;
}

/** The significance of the inspector's t-test. */
export const TTEST_ALPHA = 0.01;

export interface InspectOptions extends TraceOptions {
  width: number;
  height: number;
  seed: number;
  /** Samples of the estimate (MIS: rounded down to an even count). */
  pn?: number;
  rows?: number;
  /** Samples of the converged reference (default 16 pn). */
  referenceN?: number;
}

const isMis = (s: Strategy) => s === 'mis-balance' || s === 'mis-power';

function rowOf(r: DirectSample): SampleRow {
  const hasPoint = Number.isFinite(r.lx);
  return {
    technique: r.technique,
    direction: [r.dx, r.dy, r.dz],
    lightPoint: hasPoint ? [r.lx, r.ly, r.lz] : null,
    f: r.f,
    L: r.L,
    cosTheta: r.cosTheta,
    cosThetaL: Number.isFinite(r.cosThetaL) ? r.cosThetaL : null,
    r2: Number.isFinite(r.r2) ? r.r2 : null,
    pdf: r.pdf,
    measure: r.measure,
    pdfSolidAngle: r.pdfSolidAngle,
    weight: r.weight,
    term: r.term,
  };
}

/**
 * n samples of the radiance leaving v by `opts` (seeded by seed and stream), with the first `rows`
 * direct-light samples. Under MIS the statistics are over pairs (one sample of each technique).
 */
export function estimateAtVertex(
  scene: RenderScene,
  v: Vertex,
  opts: TraceOptions,
  n: number,
  seed: number,
  stream: number,
  rows = 0,
): { stats: Welford; rows: SampleRow[] } {
  const tr = makeTracer(scene, opts);
  const rng = new Rng(seed, stream);
  const stats = new Welford();
  const out: SampleRow[] = [];
  const rec = newDirectSample();
  const mis = isMis(opts.strategy);
  const count = mis ? Math.max(2, n - (n % 2)) : Math.max(1, n);
  let pending = 0;
  for (let s = 0; s < count; s++) {
    const want = s < rows;
    const y = pathFromVertex(tr, v, s, rng, want ? rec : undefined);
    if (want) out.push(rowOf(rec));
    if (!mis) stats.add(y);
    else if (s % 2 === 0) pending = y;
    else stats.add((pending + y) / 2);
  }
  return { stats, rows: out };
}

/** Inspect pixel (i, j) of the image of `scene` seen from `view`. */
export function inspectPixel(
  scene: RenderScene,
  view: View,
  i: number,
  j: number,
  opts: InspectOptions,
): PixelInspection {
  const cam = makeCamera(view, opts.width, opts.height);
  const d = [0, 0, 0];
  cameraRay(cam, i, j, 0.5, 0.5, d);
  const o = view.eye;
  const dv: Vec3 = [d[0], d[1], d[2]];
  let discriminant: number | null = null;
  let t: number | null = null;
  if (scene.sphere) {
    const q = intersectRaySphere(o, dv, scene.sphere.center, scene.sphere.radius);
    if (q.ok) {
      discriminant = q.discriminant;
      t = q.tHit;
    }
  }
  const hit = newHit();
  const kind = closestHit(scene, o[0], o[1], o[2], d[0], d[1], d[2], Infinity, hit);
  const base = { i, j, o, d: dv, discriminant, t, hit: kind };
  const pn = opts.pn ?? DEFAULT_PN;
  if (kind === 'none' || kind === 'light') {
    const value =
      kind === 'none'
        ? scene.environment
        : hit.nx * d[0] + hit.ny * d[1] + hit.nz * d[2] < 0
          ? scene.lights[hit.index].L
          : 0;
    return {
      ...base,
      p: kind === 'none' ? null : [hit.px, hit.py, hit.pz],
      u: null,
      v: null,
      texel: null,
      albedo: null,
      rows: [],
      estimate: value,
      stderr: 0,
      n: pn,
      reference: value,
      referenceKind: 'exact',
      referenceStderr: 0,
      tTest: null,
    };
  }
  const vx = newVertex();
  shadeVertex(scene, hit, d[0], d[1], d[2], vx);
  const est = estimateAtVertex(scene, vx, opts, pn, opts.seed, 1, opts.rows ?? DEFAULT_ROWS);
  const exact = exactRadiance(scene, vx, kind, opts.bounces);
  let reference: number;
  let referenceStderr = 0;
  const sample = { mean: est.stats.mean, variance: est.stats.variance(), n: est.stats.count };
  let tTest: TTestResult;
  if (exact !== null) {
    reference = exact;
    tTest = studentTTest(sample, exact, TTEST_ALPHA);
  } else {
    // the converged reference is always unbiased (no variant), whatever the inspected estimator is
    const refOpts: TraceOptions = { strategy: 'mis-power', bounces: opts.bounces };
    const ref = estimateAtVertex(scene, vx, refOpts, opts.referenceN ?? CONVERGED_FACTOR * pn, opts.seed, 2);
    reference = ref.stats.mean;
    referenceStderr = ref.stats.standardError();
    tTest = welchTTest(
      sample,
      { mean: ref.stats.mean, variance: ref.stats.variance(), n: ref.stats.count },
      TTEST_ALPHA,
    );
  }
  const textured = kind === 'sphere' && Number.isFinite(vx.texel);
  return {
    ...base,
    p: [vx.px, vx.py, vx.pz],
    u: textured ? vx.u : null,
    v: textured ? vx.v : null,
    texel: textured ? vx.texel : null,
    albedo: vx.glossy ? null : vx.albedo,
    rows: est.rows,
    estimate: est.stats.mean,
    stderr: est.stats.count > 1 ? est.stats.standardError() : 0,
    n: est.stats.count * (isMis(opts.strategy) ? 2 : 1),
    reference,
    referenceKind: exact !== null ? 'exact' : 'converged',
    referenceStderr,
    tTest,
  };
}
