/**
 * The direct-light estimator at a shading point: one sample of
 *
 *     L_d(p, ωₒ) = ∫ f(ωₒ, ωᵢ) L_e(ωᵢ) V cos θ dωᵢ
 *
 * by one of seven strategies, each sample's term f L cos θ / p_ω an unbiased estimate:
 *
 * - `uniform` (Q1/Q2): ωᵢ uniform on the hemisphere about n, p = 1/(2π);
 * - `cosine`: ωᵢ ∝ cos θ, p = cos θ/π (on a Lambertian surface the term is ρ L exactly);
 * - `bsdf`: the material's own lobe (cosine on Lambert, the Phong lobe on a plate);
 * - `area` (Q6(c)): a point on a light uniformly by area, p_ω = p_A r²/cos θ_l (Q6(a));
 * - `solid-angle`: a point uniformly in the light's solid angle (Ureña et al. 2013), p = 1/Ω;
 * - `mis-balance`, `mis-power`: `bsdf` and `solid-angle` combined by Veach's heuristics at equal
 *   total samples: even sample indices use the BSDF technique, odd ones the light technique, and
 *   each term is 2 w f L cos θ / p (so the mean over 2m samples is Veach's two-technique estimator
 *   with m samples each; Veach's thesis ch. 9, eq. 9.4; pbrt-v4 §13.4).
 *
 * Every pdf is converted to solid angle before it divides or weighs (pbrt-v4 §13.2.2). Hemisphere
 * and BSDF samples find the light by tracing the ray; light samples are tested by a shadow ray.
 */
import { areaToSolidAnglePdf } from '../lights/areaSampling';
import { cosineHemispherePdf, sampleCosineHemisphere } from '../sampling/cosineHemisphere';
import { sampleUniformHemisphere } from '../sampling/uniformHemisphere';
import type { Rng } from '../random/rng';
import { toWorld } from './frame';
import { closestHit } from './intersect';
import type { DirectSample, DirectScratch, Technique } from './directSample';
import { emitterCount, lightFramesAt, lightPdf, sampleEmitter, type LightFrames } from './lightSampling';
import { bsdfEval, bsdfPdf, bsdfSample, type Vertex } from './material';
import { misWeight } from './mis';
import { biasedTerm, type Bias } from './bias';
import type { RenderScene } from './scene';

export const STRATEGIES = [
  'uniform',
  'cosine',
  'bsdf',
  'area',
  'solid-angle',
  'mis-balance',
  'mis-power',
] as const;
export type Strategy = (typeof STRATEGIES)[number];

const INV_TWO_PI = 1 / (2 * Math.PI);
/** Shadow rays stop this fraction short of the light point, so the light itself is not an occluder. */
const SHADOW_EPS = 1e-7;

/** The light frames of the vertex (built once per vertex, on first need). */
function framesOf(scene: RenderScene, v: Vertex, sc: DirectScratch): LightFrames {
  if (sc.framesFor !== v || !sc.frames) {
    sc.frames = lightFramesAt(scene, v.px, v.py, v.pz);
    sc.framesFor = v;
  }
  return sc.frames;
}

/** Forget the cached light frames (call when a vertex object is refilled with a new point). */
export function resetFrames(sc: DirectScratch): void {
  sc.framesFor = null;
}

/** Trace ωᵢ (in sc.dir) from the vertex: what emits along it, into rec (L, light point, cos θ_l, r²). */
function traceEmission(scene: RenderScene, v: Vertex, sc: DirectScratch, rec: DirectSample): void {
  const o = v.origin,
    d = sc.dir;
  const kind = closestHit(scene, o[0], o[1], o[2], d[0], d[1], d[2], Infinity, sc.hit);
  const h = sc.hit;
  rec.L = 0;
  rec.light = -2;
  if (kind === 'none') {
    if (scene.environment > 0) {
      rec.L = scene.environment;
      rec.light = -1;
    }
    return;
  }
  if (kind !== 'light') return;
  const l = scene.lights[h.index];
  const cl = -(d[0] * h.nx + d[1] * h.ny + d[2] * h.nz);
  rec.lx = h.px;
  rec.ly = h.py;
  rec.lz = h.pz;
  const rx = h.px - v.px,
    ry = h.py - v.py,
    rz = h.pz - v.pz;
  rec.r2 = rx * rx + ry * ry + rz * rz;
  rec.cosThetaL = cl;
  if (cl > 0) {
    rec.L = l.L;
    rec.light = h.index;
  }
}

/** A hemisphere or BSDF sample (technique t): direction, densities, f, cos θ and what it reaches. */
function directionSample(
  scene: RenderScene,
  v: Vertex,
  t: Technique,
  rng: Rng,
  sc: DirectScratch,
  rec: DirectSample,
): void {
  const u1 = rng.nextFloat(),
    u2 = rng.nextFloat();
  const d = sc.dir;
  let cos: number;
  if (t === 'bsdf') {
    const lz = bsdfSample(v, u1, u2, d);
    // on Lambert the lobe's own z is cos θ: used for both cos θ and the pdf, f cos θ / p is ρ exactly
    cos = v.glossy ? d[0] * v.nx + d[1] * v.ny + d[2] * v.nz : lz;
    rec.pdf = v.glossy ? bsdfPdf(v, d[0], d[1], d[2]) : cosineHemispherePdf(0, 0, lz);
  } else {
    if (t === 'uniform') sampleUniformHemisphere(u1, u2, sc.buf);
    else sampleCosineHemisphere(u1, u2, sc.buf);
    cos = sc.buf[2];
    toWorld(v.frameN, sc.buf[0], sc.buf[1], sc.buf[2], d);
    rec.pdf = t === 'uniform' ? INV_TWO_PI : cosineHemispherePdf(0, 0, cos);
  }
  rec.dx = d[0];
  rec.dy = d[1];
  rec.dz = d[2];
  rec.measure = 'solid-angle';
  rec.pdfSolidAngle = rec.pdf;
  rec.cosTheta = cos;
  rec.f = cos > 0 ? bsdfEval(v, d[0], d[1], d[2]) : 0;
  if (rec.f > 0 && rec.pdf > 0) traceEmission(scene, v, sc, rec);
  else rec.L = 0;
}

/** A light sample (by area or solid angle), its visibility tested by a shadow ray. */
function emitterSample(
  scene: RenderScene,
  v: Vertex,
  t: 'area' | 'solid-angle',
  rng: Rng,
  sc: DirectScratch,
  rec: DirectSample,
): void {
  const u0 = emitterCount(scene) > 1 ? rng.nextFloat() : 0;
  const u1 = rng.nextFloat(),
    u2 = rng.nextFloat();
  const frames = t === 'solid-angle' ? framesOf(scene, v, sc) : null;
  rec.measure = t === 'area' ? 'area' : 'solid-angle';
  rec.L = 0;
  rec.f = 0;
  rec.cosTheta = 0;
  rec.pdf = 0;
  rec.pdfSolidAngle = 0;
  rec.light = -2;
  const e = sc.emitter;
  if (!sampleEmitter(scene, frames, t, u0, u1, u2, e, sc.buf)) return;
  const d = sc.dir;
  let dist = Infinity;
  if (e.light < 0) {
    d[0] = e.x;
    d[1] = e.y;
    d[2] = e.z;
    rec.measure = 'solid-angle';
    rec.pdf = e.pdf;
    rec.pdfSolidAngle = e.pdf;
  } else {
    const rx = e.x - v.px,
      ry = e.y - v.py,
      rz = e.z - v.pz;
    const r2 = rx * rx + ry * ry + rz * rz;
    dist = Math.sqrt(r2);
    d[0] = rx / dist;
    d[1] = ry / dist;
    d[2] = rz / dist;
    const n = scene.lights[e.light].rect.normal;
    const cl = -(d[0] * n[0] + d[1] * n[1] + d[2] * n[2]);
    rec.lx = e.x;
    rec.ly = e.y;
    rec.lz = e.z;
    rec.r2 = r2;
    rec.cosThetaL = cl;
    rec.pdf = e.pdf;
    rec.pdfSolidAngle = t === 'area' ? areaToSolidAnglePdf(e.pdf, r2, cl) : e.pdf;
    if (!(cl > 0)) return;
  }
  rec.dx = d[0];
  rec.dy = d[1];
  rec.dz = d[2];
  rec.cosTheta = d[0] * v.nx + d[1] * v.ny + d[2] * v.nz;
  if (!(rec.cosTheta > 0) || !(rec.pdfSolidAngle > 0)) return;
  rec.f = bsdfEval(v, d[0], d[1], d[2]);
  if (!(rec.f > 0)) return;
  const o = v.origin;
  const tMax = e.light < 0 ? Infinity : dist * (1 - SHADOW_EPS);
  if (closestHit(scene, o[0], o[1], o[2], d[0], d[1], d[2], tMax, sc.hit) !== 'none') return;
  rec.L = e.light < 0 ? scene.environment : scene.lights[e.light].L;
  rec.light = e.light;
}

/**
 * Draw sample number `index` of the direct-light estimator at v by `strategy` from rng; fill rec
 * and return its term (radiance). For MIS the index's parity picks the technique (see the module
 * comment). `bias` other than 'none' computes a deliberately wrong term (./bias).
 */
export function directSample(
  scene: RenderScene,
  v: Vertex,
  strategy: Strategy,
  index: number,
  rng: Rng,
  sc: DirectScratch,
  rec: DirectSample,
  bias: Bias = 'none',
): number {
  rec.lx = rec.ly = rec.lz = NaN;
  rec.cosThetaL = NaN;
  rec.r2 = NaN;
  rec.weight = 1;
  const mis = strategy === 'mis-balance' || strategy === 'mis-power';
  const t: Technique = mis ? (index % 2 === 0 ? 'bsdf' : 'solid-angle') : strategy;
  rec.technique = t;
  if (t === 'area' || t === 'solid-angle') emitterSample(scene, v, t, rng, sc, rec);
  else directionSample(scene, v, t, rng, sc, rec);
  const contrib = rec.f * rec.L;
  if (!(contrib > 0) || !(rec.pdfSolidAngle > 0)) {
    rec.term = 0;
    if (mis) rec.weight = 0;
    return 0;
  }
  let factor = 1;
  if (mis) {
    const heuristic = strategy === 'mis-balance' ? 'balance' : 'power';
    const frames = framesOf(scene, v, sc);
    const other =
      t === 'bsdf'
        ? lightPdf(scene, frames, rec.light, rec.lx, rec.ly, rec.lz)
        : bsdfPdf(v, rec.dx, rec.dy, rec.dz);
    rec.weight = misWeight(heuristic, rec.pdfSolidAngle, other);
    factor = 2 * rec.weight;
  }
  rec.term = (factor * contrib * rec.cosTheta) / rec.pdfSolidAngle;
  if (bias !== 'none') rec.term = biasedTerm(bias, rec.term, t, rec.cosThetaL);
  return rec.term;
}
