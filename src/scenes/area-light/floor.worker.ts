/**
 * Worker for #/area-light: progressive floor images for the three strategies (side by side), and
 * the run-time-against-error study. All math is in model.ts / core; this file only loops, times
 * and reports progress.
 */
import { exposeTasks, yieldToEventLoop, type ProgressFn } from '../../workers/expose';
import { estimateAreaLight, type AreaLightSetup, type LightStrategy } from '../../core/lights';
import {
  STRATEGIES,
  TIMING_COUNTS,
  TIMING_RUNS,
  buildModel,
  convergence,
  estimateAll,
  type StrategyEstimate,
  floorPass,
  imageRmse,
  referenceImage,
  rmseOfRuns,
  type FloorJob,
  type TimingPoint,
} from './model';
import type { AreaLightParams } from './params';

/** Samples per pixel added by each pass: 1, 1, 2, 4, … (total doubles every pass). */
export const PASS_SPP = [1, 1, 2, 4, 8, 16, 32] as const;

/** What the render task reports after each pass (and returns at the end). */
export interface FloorFrame {
  size: number;
  spp: number;
  /** Mean images (sum / spp), one per strategy, in STRATEGIES order. */
  images: Float32Array[];
  reference: Float32Array;
  rmse: number[];
  /** Milliseconds spent per strategy so far. */
  ms: number[];
  done: boolean;
}

function frame(job: FloorJob, sums: Float64Array[], spp: number, ref: Float32Array, ms: number[], done: boolean): FloorFrame {
  const images = sums.map((s) => {
    const img = new Float32Array(s.length);
    for (let k = 0; k < s.length; k++) img[k] = s[k]! / spp;
    return img;
  });
  return { size: job.size, spp, images, reference: ref.slice(), rmse: sums.map((s) => imageRmse(s, spp, ref)), ms: ms.slice(), done };
}

/** Seconds per estimate of n samples: repeat until ≥ budgetMs has passed, divide by the count. */
function timeOne(setup: AreaLightSetup, s: LightStrategy, n: number, seed: number, budgetMs: number): number {
  let reps = 0;
  const t0 = performance.now();
  let t1 = t0;
  while (t1 - t0 < budgetMs && reps < 1e6) {
    estimateAreaLight(setup, s, n, seed, 500 + reps);
    reps++;
    t1 = performance.now();
  }
  return (t1 - t0) / 1000 / reps;
}

exposeTasks({
  /** Convergence series of the three strategies (log-spaced checkpoints up to nMax). */
  convergence: async (args: { params: AreaLightParams; nMax: number }, progress: ProgressFn) => {
    progress(0);
    return convergence(buildModel(args.params), args.nMax, args.params.seed);
  },

  /** The three estimates for large n (the scene computes small n on the main thread; same numbers). */
  estimates: async (params: AreaLightParams, progress: ProgressFn): Promise<StrategyEstimate[]> => {
    progress(0);
    return estimateAll(buildModel(params), params.n, params.seed);
  },

  render: async (job: FloorJob, progress: ProgressFn): Promise<FloorFrame> => {
    const ref = referenceImage(job);
    const sums = STRATEGIES.map(() => new Float64Array(job.size * job.size));
    const ms = STRATEGIES.map(() => 0);
    let spp = 0;
    const total = PASS_SPP.reduce((a, b) => a + b, 0);
    for (let pass = 0; pass < PASS_SPP.length; pass++) {
      const k = PASS_SPP[pass]!;
      STRATEGIES.forEach((s, i) => {
        const t0 = performance.now();
        floorPass(job, s, k, pass, sums[i]!);
        ms[i]! += performance.now() - t0;
      });
      spp += k;
      if (pass < PASS_SPP.length - 1) {
        progress(spp / total, frame(job, sums, spp, ref, ms, false));
        await yieldToEventLoop();
      }
    }
    return frame(job, sums, spp, ref, ms, true);
  },

  timing: async (params: AreaLightParams, progress: ProgressFn): Promise<TimingPoint[]> => {
    const m = buildModel(params);
    // Warm up every (strategy, N) first so the JIT has optimized the kernels before any timing;
    // otherwise whichever strategy runs first pays for compilation.
    for (let round = 0; round < 2; round++)
      for (const s of STRATEGIES) for (const n of TIMING_COUNTS) timeOne(m.setup, s, n, params.seed, 2);
    progress(0.1);
    await yieldToEventLoop();
    const out: TimingPoint[] = [];
    const steps = STRATEGIES.length * TIMING_COUNTS.length;
    let done = 0;
    for (const n of TIMING_COUNTS)
      for (const s of STRATEGIES) {
        const rmse = rmseOfRuns(m, s, n, TIMING_RUNS, params.seed);
        // Best of three timings (each ≥ 12 ms of repeated estimates, so timer resolution is moot).
        const seconds = Math.min(timeOne(m.setup, s, n, params.seed, 12), timeOne(m.setup, s, n, params.seed, 12), timeOne(m.setup, s, n, params.seed, 12));
        out.push({ strategy: s, n, rmse, seconds });
        progress(0.1 + (0.9 * ++done) / steps);
        await yieldToEventLoop();
      }
    out.sort((a, b) => STRATEGIES.indexOf(a.strategy) - STRATEGIES.indexOf(b.strategy) || a.n - b.n);
    return out;
  },
});
