/**
 * The FLIP measurement as a worker task (./flip.worker.ts runs it; ./flipWorker.ts starts that
 * worker). A 96 × 96 FLIP takes tens of milliseconds, so the page never runs it itself.
 */
import { flipOfRgba8, magmaErrorImage } from '../core/image/flipRgba8';

/** Two 8-bit sRGB images of one size (RGBA, rows from the top), exactly as the page shows them. */
export interface FlipArgs {
  width: number;
  height: number;
  reference: Uint8ClampedArray;
  test: Uint8ClampedArray;
}

/** The pooled FLIP figures and the magma error map (RGBA8) of a {@link FlipArgs} pair. */
export interface FlipResult {
  mean: number;
  weightedMedian: number;
  max: number;
  errorMap: Uint8ClampedArray;
  /** Each pixel's FLIP error in [0, 1], row-major (what the loupe reads). */
  errors: Float32Array;
}

/** LDR-FLIP of the pair at the reference tool's default viewing conditions. */
export async function flipTask(args: FlipArgs): Promise<FlipResult> {
  const { width, height } = args;
  const m = flipOfRgba8({ width, height, data: args.reference }, { width, height, data: args.test });
  const map = magmaErrorImage(m.map, width, height);
  return {
    mean: m.pooled.mean,
    weightedMedian: m.pooled.weightedMedian,
    max: m.pooled.max,
    errorMap: map.data as Uint8ClampedArray,
    errors: Float32Array.from(m.map),
  };
}

/** The tasks of ./flip.worker.ts. */
export const FLIP_TASKS = { flip: flipTask };
export type FlipTasks = typeof FLIP_TASKS;
