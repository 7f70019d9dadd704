/**
 * The error of an estimator measured two ways (Celarek, Jakob, Wimmer and Lehtinen, "Quantifying
 * the Error of Light Transport Algorithms", EGSR 2019): from K independent runs alone, as the
 * per-pixel sample variance s² (no reference needed: the expected MSE of one run, if the estimator
 * is unbiased), and against the exact reference, as the mean of (x − ref)² over the same runs (the
 * MSE that was actually made: variance plus bias²). For an unbiased estimator the two agree within
 * their noise; a biased one makes more error than its own spread shows.
 */
import { stdDevImage } from '../image/stdDevImage';
import { runSeed } from '../random/rng';
import { makeCpuRenderer, renderImage } from './cpuRenderer';
import type { TraceOptions } from './pathTrace';
import type { RenderScene, View } from './scene';

/** K renders of `spp` samples per pixel, each from its own seed (runSeed(seed, k + 1)). */
export function independentRuns(
  scene: RenderScene,
  view: View,
  res: number,
  trace: TraceOptions,
  seed: number,
  runs: number,
  spp: number,
): Float64Array[] {
  const out: Float64Array[] = [];
  for (let k = 0; k < runs; k++)
    out.push(
      renderImage(makeCpuRenderer(scene, view, res, res, trace, runSeed(seed, k + 1)), res, res, spp, 1),
    );
  return out;
}

export interface ExpectedError {
  /** Per-pixel sample standard deviation over the runs. */
  sd: Float64Array;
  /** Mean of s² over the pixels with an exact reference: the MSE the runs' spread predicts. */
  expectedMse: number;
  /** Mean of (x − ref)² over the same pixels and every run: the MSE the runs made. */
  measuredMse: number;
  /** How many pixels have an exact reference (NaN elsewhere in `reference`). */
  pixels: number;
}

export function expectedError(runs: readonly Float64Array[], reference: ArrayLike<number>): ExpectedError {
  const sd = stdDevImage(runs);
  let s2 = 0;
  let e2 = 0;
  let pixels = 0;
  for (let i = 0; i < sd.length; i++) {
    const ref = reference[i];
    if (!Number.isFinite(ref) || !Number.isFinite(sd[i])) continue;
    pixels++;
    s2 += sd[i] * sd[i];
    for (const r of runs) e2 += (r[i] - ref) ** 2;
  }
  return {
    sd,
    expectedMse: pixels ? s2 / pixels : NaN,
    measuredMse: pixels ? e2 / (pixels * runs.length) : NaN,
    pixels,
  };
}
