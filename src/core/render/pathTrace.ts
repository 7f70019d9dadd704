/**
 * The path tracer: radiance arriving along a ray, as one sample of the rendering equation
 * (Kajiya 1986) by next-event estimation (pbrt-v4 §13.4, `PathIntegrator`). At each surface vertex
 * the direct light is estimated by the chosen strategy (directLight.ts); the path then continues
 * along a direction drawn from the BSDF, whose hits on emitters are not counted again (the direct
 * estimate already holds them). `bounces` = 1 is direct light only; up to 8 vertices are shaded.
 * From the third vertex on the path survives with probability q = min(1, β) (β its throughput)
 * and β is divided by q: Russian roulette, unbiased (Arvo & Kirk 1990; pbrt-v4 §13.1.3).
 */
import type { Rng } from '../random/rng';
import { closestHit } from './intersect';
import { directSample, resetFrames, type Strategy } from './directLight';
import { newDirectSample, newDirectScratch, type DirectSample, type DirectScratch } from './directSample';
import { bsdfEval, bsdfPdf, bsdfSample, newVertex, shadeVertex, type Vertex } from './material';
import type { RenderScene } from './scene';
import type { Bias } from './bias';

/** Fewest and most shaded vertices along a path. */
export const MIN_BOUNCES = 1;
export const MAX_BOUNCES = 8;
/** Russian roulette starts at this vertex. */
export const ROULETTE_FROM = 3;

/** The estimator's settings. */
export interface TraceOptions {
  strategy: Strategy;
  bounces: number;
  /** A deliberately biased variant of the direct-light terms (./bias; default none). */
  bias?: Bias;
}

/** A path tracer's reusable state: the scene, its options and its buffers. */
export interface Tracer {
  scene: RenderScene;
  strategy: Strategy;
  bounces: number;
  bias: Bias;
  direct: DirectScratch;
  rec: DirectSample;
  a: Vertex;
  b: Vertex;
  dir: Float64Array;
}

export function makeTracer(scene: RenderScene, opts: TraceOptions): Tracer {
  const bounces = Math.min(MAX_BOUNCES, Math.max(MIN_BOUNCES, Math.round(opts.bounces) || 1));
  return {
    scene,
    strategy: opts.strategy,
    bounces,
    bias: opts.bias ?? 'none',
    direct: newDirectScratch(),
    rec: newDirectSample(),
    a: newVertex(),
    b: newVertex(),
    dir: new Float64Array(3),
  };
}

/**
 * One sample (number `index`, whose parity picks the MIS technique) of the radiance leaving the
 * surface vertex v towards ωₒ, reflected light only (v itself does not emit). `first`, when
 * given, receives the first vertex's direct-light sample. v is left unchanged.
 */
export function pathFromVertex(tr: Tracer, v: Vertex, index: number, rng: Rng, first?: DirectSample): number {
  const { scene } = tr;
  let cur = v;
  let spare = tr.a;
  let L = 0;
  let beta = 1;
  for (let depth = 1; ; depth++) {
    resetFrames(tr.direct);
    const rec = depth === 1 && first ? first : tr.rec;
    L += beta * directSample(scene, cur, tr.strategy, index, rng, tr.direct, rec, tr.bias);
    if (depth >= tr.bounces) break;
    const d = tr.dir;
    bsdfSample(cur, rng.nextFloat(), rng.nextFloat(), d);
    const cos = d[0] * cur.nx + d[1] * cur.ny + d[2] * cur.nz;
    const f = bsdfEval(cur, d[0], d[1], d[2]);
    const pdf = bsdfPdf(cur, d[0], d[1], d[2]);
    if (!(f > 0 && cos > 0 && pdf > 0)) break;
    beta *= (f * cos) / pdf;
    if (depth >= ROULETTE_FROM) {
      const q = Math.min(1, beta);
      if (!(rng.nextFloat() < q)) break;
      beta /= q;
    }
    const o = cur.origin;
    const kind = closestHit(scene, o[0], o[1], o[2], d[0], d[1], d[2], Infinity, tr.direct.hit);
    if (kind === 'none' || kind === 'light') break;
    shadeVertex(scene, tr.direct.hit, d[0], d[1], d[2], spare);
    cur = spare;
    spare = spare === tr.a ? tr.b : tr.a;
  }
  resetFrames(tr.direct);
  return L;
}

/**
 * One sample of the radiance arriving at o along the unit direction d: the environment for a miss,
 * a light's radiance (its front; its back is black), else the surface's reflected light.
 */
export function radiance(
  tr: Tracer,
  ox: number,
  oy: number,
  oz: number,
  dx: number,
  dy: number,
  dz: number,
  index: number,
  rng: Rng,
): number {
  const hit = tr.direct.hit;
  const kind = closestHit(tr.scene, ox, oy, oz, dx, dy, dz, Infinity, hit);
  if (kind === 'none') return tr.scene.environment;
  if (kind === 'light') return hit.nx * dx + hit.ny * dy + hit.nz * dz < 0 ? tr.scene.lights[hit.index].L : 0;
  shadeVertex(tr.scene, hit, dx, dy, dz, tr.b);
  return pathFromVertex(tr, tr.b, index, rng);
}
