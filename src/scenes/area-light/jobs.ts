/**
 * The long computations of #/area-light as plain async functions of plain data: the convergence
 * series, the three estimates for large n, the progressive floor images of the three strategies,
 * and the run-time-against-error study. They run in floor.worker.ts and in unit tests alike; all
 * math is in model.ts / core, these only loop, time and report progress.
 */
import { estimateAreaLight, type AreaLightSetup, type LightStrategy } from '../../core/lights';
import { STRATEGIES } from './strategies';
import {
  TIMING_COUNTS,
  TIMING_RUNS,
  buildModel,
  convergence,
  estimateAll,
  rmseOfRuns,
  type StrategyEstimate,
  type TimingPoint,
} from './model';
import { PASS_SPP, floorPass, imageRmse, referenceImage, type FloorJob } from './floor';
import type { AreaLightParams } from './params';

import { yieldToEventLoop as tick, type ProgressFn as Progress } from '../../workers/expose';
import { workerFactory } from '../../workers/protocol';

const now = (): number => performance.now();

export { PASS_SPP };

/** What the render job reports after each pass (and returns at the end). */
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
  /** In the final result: every pass in order (passes[i] has PASS_TOTAL[i] samples per pixel; their own `passes` is empty). Empty in partials. */
  passes: FloorFrame[];
}

function frame(
  job: FloorJob,
  sums: Float64Array[],
  spp: number,
  ref: Float32Array,
  ms: number[],
  done: boolean,
): FloorFrame {
  const images = sums.map((s) => {
    const img = new Float32Array(s.length);
    for (let k = 0; k < s.length; k++) img[k] = s[k] / spp;
    return img;
  });
  return {
    size: job.size,
    spp,
    images,
    reference: ref.slice(),
    rmse: sums.map((s) => imageRmse(s, spp, ref)),
    ms: ms.slice(),
    done,
    passes: [],
  };
}

/** Seconds per estimate of n samples: repeat until ≥ budgetMs has passed, divide by the count. */
function timeOne(setup: AreaLightSetup, s: LightStrategy, n: number, seed: number, budgetMs: number): number {
  let reps = 0;
  const t0 = now();
  let t1 = t0;
  while (t1 - t0 < budgetMs && reps < 1e6) {
    estimateAreaLight(setup, s, n, seed, 500 + reps);
    reps++;
    t1 = now();
  }
  return (t1 - t0) / 1000 / reps;
}

/** Convergence series of the three strategies (log-spaced checkpoints up to nMax). */
export async function convergenceJob(
  args: { params: AreaLightParams; nMax: number },
  progress: Progress = () => {},
) {
  progress(0);
  return convergence(buildModel(args.params), args.nMax, args.params.seed);
}

/** The three estimates for large n (the scene computes small n on the main thread; same numbers). */
export async function estimatesJob(
  params: AreaLightParams,
  progress: Progress = () => {},
): Promise<StrategyEstimate[]> {
  progress(0);
  return estimateAll(buildModel(params), params.n, params.seed);
}

/** The floor rendered progressively with each strategy, one partial frame per pass. */
export async function renderJob(
  job: FloorJob,
  progress: Progress<FloorFrame> = () => {},
): Promise<FloorFrame> {
  const ref = referenceImage(job);
  const sums = STRATEGIES.map(() => new Float64Array(job.size * job.size));
  const ms = STRATEGIES.map(() => 0);
  const passes: FloorFrame[] = [];
  let spp = 0;
  const total = PASS_SPP.reduce((a, b) => a + b, 0);
  for (let pass = 0; pass < PASS_SPP.length; pass++) {
    const k = PASS_SPP[pass];
    STRATEGIES.forEach((s, i) => {
      const t0 = now();
      floorPass(job, s, k, pass, sums[i]);
      ms[i] += now() - t0;
    });
    spp += k;
    passes.push(frame(job, sums, spp, ref, ms, pass === PASS_SPP.length - 1));
    if (pass < PASS_SPP.length - 1) {
      // A copy: the partial's buffers are transferred, and `passes` keeps its own.
      const p = passes[pass];
      progress(spp / total, {
        ...p,
        images: p.images.map((im) => im.slice()),
        reference: p.reference.slice(),
      });
      await tick();
    }
  }
  return { ...passes[passes.length - 1], passes };
}

/** RMSE over TIMING_RUNS runs and the measured time of one estimate, per strategy and N. */
export async function timingJob(
  params: AreaLightParams,
  progress: Progress = () => {},
  budgetMs = 12,
): Promise<TimingPoint[]> {
  const m = buildModel(params);
  // Warm up every (strategy, N) first so the JIT has optimized the kernels before any timing;
  // otherwise whichever strategy runs first pays for compilation.
  for (let round = 0; round < 2; round++)
    for (const s of STRATEGIES) for (const n of TIMING_COUNTS) timeOne(m.setup, s, n, params.seed, 2);
  progress(0.1);
  await tick();
  const out: TimingPoint[] = [];
  const steps = STRATEGIES.length * TIMING_COUNTS.length;
  let done = 0;
  for (const n of TIMING_COUNTS)
    for (const s of STRATEGIES) {
      const rmse = rmseOfRuns(m, s, n, TIMING_RUNS, params.seed);
      // Best of three timings (each ≥ budgetMs of repeated estimates, so timer resolution is moot).
      const seconds = Math.min(
        timeOne(m.setup, s, n, params.seed, budgetMs),
        timeOne(m.setup, s, n, params.seed, budgetMs),
        timeOne(m.setup, s, n, params.seed, budgetMs),
      );
      out.push({ strategy: s, n, rmse, seconds });
      progress(0.1 + (0.9 * ++done) / steps);
      await tick();
    }
  out.sort((a, b) => STRATEGIES.indexOf(a.strategy) - STRATEGIES.indexOf(b.strategy) || a.n - b.n);
  return out;
}

/** The tasks floor.worker.ts runs, by name. */
export const AREA_LIGHT_TASKS = {
  convergence: convergenceJob,
  estimates: estimatesJob,
  render: renderJob,
  timing: timingJob,
};

/** The worker's tasks, for the page's side. */
export type AreaLightTasks = typeof AREA_LIGHT_TASKS;

/** The scene's worker, as the page starts it (one fresh worker per run: src/workers/run.ts). */
export const makeWorker = workerFactory<AreaLightTasks>(
  () => new Worker(new URL('./floor.worker.ts', import.meta.url), { type: 'module' }),
);
