/**
 * Collating the class's results files in the results page's worker (./results.worker.ts): the one
 * factory that starts it, and the call the page makes. A crafted file can make grading slow (every
 * attempt is checked again from its typed text); in the worker it holds up nothing on the page,
 * and Cancel ends it at once (the worker is terminated).
 */
import { workerFactory } from '../workers/protocol';
import { isCancelled, runWorkerTask } from '../workers/run';
import type { Collation, InputFile } from './collate';
import type { CollateStep, ResultsTasks } from './results.worker';

/** Starts a results worker: the one place that names the worker's file. */
export const makeResultsWorker = workerFactory<ResultsTasks>(
  () => new Worker(new URL('./results.worker.ts', import.meta.url), { type: 'module' }),
);

/** A collation that stopped: `file` is the file it was checking (null between files). */
export class CollationFailed extends Error {
  constructor(
    readonly file: string | null,
    reason: string,
  ) {
    super(file ? `Checking stopped at ${file}: ${reason}.` : `Checking stopped: ${reason}.`);
    this.name = 'CollationFailed';
  }
}

/**
 * Collate `files` in a fresh worker; `onStep` hears of each file as it starts and ends. Rejects
 * with an AbortError when `signal` aborts, and with {@link CollationFailed} (naming the file it
 * was on) when the worker cannot start, refuses or dies.
 */
export async function collateInWorker(
  files: InputFile[],
  onStep: (step: CollateStep) => void,
  signal: AbortSignal,
  make = makeResultsWorker,
): Promise<Collation> {
  let current: string | null = null;
  try {
    return await runWorkerTask(make, 'collate', files, {
      signal,
      onProgress: (_f, step) => {
        if (!step) return;
        current = step.current ?? null;
        onStep(step);
      },
    });
  } catch (e) {
    if (isCancelled(e)) throw e;
    throw new CollationFailed(current, e instanceof Error ? e.message : String(e));
  }
}
