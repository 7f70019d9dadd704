/**
 * Equal-time comparison of direct-light strategies, the way rendering papers argue (pbrt-v4 §13;
 * the equal-time figures of Veach's thesis ch. 9): each strategy renders the same image, pass
 * after pass of one sample per pixel, for the same time budget, and its error against the exact
 * reference is recorded after every pass. Its curve of relMSE against time is what a log–log plot
 * shows (a slope of −1 for any unbiased estimator: error ∝ variance/N ∝ 1/time); the error each
 * reaches at the budget ranks the strategies at equal time, and the time each needs to reach one
 * error (read off the same curve) ranks them at equal error.
 *
 * Beside relMSE, the perceptual error rendering papers now report: the image's mean LDR-FLIP
 * against the reference (./displayFlip), measured after passes 1, 2, 4, 8, … and the last (even
 * spacing on the log axis the curve is drawn on). Only the passes are timed, not the measuring.
 *
 * The clock is a parameter (`now`, in ms), so that a test can give the strategies a clock that
 * counts work instead of time and check everything else deterministically.
 */
import { relMse } from '../image/relMse';
import { displayFlipMean } from './displayFlip';
import type { Strategy } from './directLight';
import { makeCpuRenderer, newAccumulation, renderTilePass, resolveImage } from './cpuRenderer';
import type { TraceOptions } from './pathTrace';
import type { RenderScene, View } from './scene';

export interface StrategyRun {
  strategy: Strategy;
  /** Samples per pixel reached within the budget (one per pass; at least one pass always runs). */
  spp: number;
  /** The time the passes took (ms, on the clock given). */
  ms: number;
  /** relMSE of the final image against the reference, over the pixels that have one. */
  relMse: number;
  /** Mean FLIP of the final image against the reference, over the pixels that have one. */
  flip: number;
  /**
   * After each pass: the time so far, the image's relMSE, and its mean FLIP where measured (after
   * passes 1, 2, 4, … and the last; NaN after the others): the curves of the log–log plots.
   */
  curve: { ms: number[]; relMse: number[]; flip: number[] };
  /** The final image (mean radiance per pixel, row-major). */
  image: Float64Array;
}

/**
 * Render the image with strategy `strategy` (bounces and bias from `trace`) for `budgetMs`, in
 * passes of one sample per pixel, and measure each pass against `reference` (NaN where a pixel has
 * no exact value). At most `maxPasses` passes run.
 */
export function runForTime(
  scene: RenderScene,
  view: View,
  res: number,
  trace: TraceOptions,
  seed: number,
  reference: Float64Array,
  budgetMs: number,
  now: () => number,
  maxPasses = 4096,
): StrategyRun {
  const r = makeCpuRenderer(scene, view, res, res, trace, seed);
  const acc = newAccumulation(res, res);
  const image = new Float64Array(res * res);
  const whole = { x0: 0, y0: 0, w: res, h: res };
  const curve = { ms: [] as number[], relMse: [] as number[], flip: [] as number[] };
  let ms = 0;
  let pass = 0;
  do {
    const t = now();
    renderTilePass(r, acc, whole, pass, 1);
    resolveImage(acc, image);
    ms += now() - t;
    pass++;
    curve.ms.push(ms);
    curve.relMse.push(relMse(image, reference));
    // after passes 1, 2, 4, 8, …
    curve.flip.push((pass & (pass - 1)) === 0 ? displayFlipMean(image, reference, res) : NaN);
  } while (ms < budgetMs && pass < maxPasses);
  if (Number.isNaN(curve.flip[pass - 1])) curve.flip[pass - 1] = displayFlipMean(image, reference, res);
  return {
    strategy: trace.strategy,
    spp: pass,
    ms,
    relMse: curve.relMse[pass - 1],
    flip: curve.flip[pass - 1],
    curve,
    image,
  };
}

/**
 * The first time on `run`'s curve at which its relMSE is at or below `target` (null: not within
 * its budget). The curve is noisy, so this is when the run first reached the error, not a fit.
 */
export function timeToError(run: StrategyRun, target: number): number | null {
  for (let k = 0; k < run.curve.ms.length; k++) if (run.curve.relMse[k] <= target) return run.curve.ms[k];
  return null;
}

/** The strategies' indices from the lowest relMSE to the highest (NaN last), for a ranking. */
export function rankByError(runs: readonly StrategyRun[]): number[] {
  const key = (k: number) => (Number.isFinite(runs[k].relMse) ? runs[k].relMse : Infinity);
  return runs.map((_, k) => k).sort((a, b) => key(a) - key(b));
}

/**
 * The error target of the equal-error comparison: the largest relMSE any strategy reached at the
 * budget, so that every strategy reaches it within its run and the times compare.
 */
export function equalErrorTarget(runs: readonly StrategyRun[]): number {
  let worst = NaN;
  for (const r of runs) if (Number.isFinite(r.relMse) && !(r.relMse <= worst)) worst = r.relMse;
  return worst;
}
