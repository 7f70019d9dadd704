/**
 * The CPU renderer, in float64: a batched kernel that adds one pass of `spp` samples per pixel to
 * a rectangular tile of a caller-owned accumulation buffer, so a picture refines progressively
 * (pass after pass) and splits over workers (tile by tile). Pixel (i, j)'s sample s of pass k
 * draws from its own generator, Rng(seed ⊕ k, j · width + i), so the image does not depend on how
 * the work was split or in which order the tiles ran. Each sample shoots the ray through a
 * uniformly jittered point of the pixel (a box filter over the pixel) and carries the global sample
 * index k · spp + s, whose parity picks the MIS technique (equal total samples).
 */
import { Rng, runSeed } from '../random/rng';
import { cameraRay, makeCamera, type Camera } from './camera';
import { makeTracer, radiance, type TraceOptions, type Tracer } from './pathTrace';
import type { RenderScene, View } from './scene';

/** A rectangle of pixels: columns x0 … x0 + w − 1, rows y0 … y0 + h − 1. */
export interface Tile {
  x0: number;
  y0: number;
  w: number;
  h: number;
}

/** A progressive image: per-pixel sums of samples and the number of samples in each. */
export interface Accumulation {
  width: number;
  height: number;
  sum: Float64Array;
  count: Uint32Array;
}

export function newAccumulation(width: number, height: number): Accumulation {
  return { width, height, sum: new Float64Array(width * height), count: new Uint32Array(width * height) };
}

/** A renderer for one scene, view, size and estimator: camera and tracer built once. */
export interface CpuRenderer {
  cam: Camera;
  tracer: Tracer;
  seed: number;
  dir: Float64Array;
}

export function makeCpuRenderer(
  scene: RenderScene,
  view: View,
  width: number,
  height: number,
  opts: TraceOptions,
  seed: number,
): CpuRenderer {
  return {
    cam: makeCamera(view, width, height),
    tracer: makeTracer(scene, opts),
    seed,
    dir: new Float64Array(3),
  };
}

/**
 * Add pass number `pass` (spp samples per pixel) over `tile` to `acc`: sum += the samples,
 * count += spp, and, when `sumSq` is given (one value per pixel), sumSq += the samples' squares.
 * Returns the number of paths traced.
 */
export function renderTilePass(
  r: CpuRenderer,
  acc: Accumulation,
  tile: Tile,
  pass: number,
  spp: number,
  sumSq?: Float64Array,
): number {
  const { cam, tracer, dir } = r;
  const e = cam.eye;
  const passSeed = runSeed(r.seed, pass);
  const x1 = Math.min(acc.width, tile.x0 + tile.w),
    y1 = Math.min(acc.height, tile.y0 + tile.h);
  let paths = 0;
  for (let j = Math.max(0, tile.y0); j < y1; j++) {
    for (let i = Math.max(0, tile.x0); i < x1; i++) {
      const k = j * acc.width + i;
      const rng = new Rng(passSeed, k);
      let s = 0,
        s2 = 0;
      for (let q = 0; q < spp; q++) {
        cameraRay(cam, i, j, rng.nextFloat(), rng.nextFloat(), dir);
        const x = radiance(tracer, e[0], e[1], e[2], dir[0], dir[1], dir[2], pass * spp + q, rng);
        s += x;
        s2 += x * x;
      }
      acc.sum[k] += s;
      if (sumSq) sumSq[k] += s2;
      acc.count[k] += spp;
      paths += spp;
    }
  }
  return paths;
}

/** The image so far: sum / count per pixel (0 where no sample has arrived), into out. */
export function resolveImage(
  acc: Accumulation,
  out = new Float64Array(acc.width * acc.height),
): Float64Array {
  for (let k = 0; k < out.length; k++) out[k] = acc.count[k] > 0 ? acc.sum[k] / acc.count[k] : 0;
  return out;
}

/** Render `passes` passes of `spp` over the whole image in one go (tests, references, the bench). */
export function renderImage(
  r: CpuRenderer,
  width: number,
  height: number,
  passes: number,
  spp: number,
): Float64Array {
  const acc = newAccumulation(width, height);
  for (let p = 0; p < passes; p++) renderTilePass(r, acc, { x0: 0, y0: 0, w: width, h: height }, p, spp);
  return resolveImage(acc);
}
