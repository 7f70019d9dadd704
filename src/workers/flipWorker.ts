/**
 * The FLIP worker, as a page starts it (one fresh worker per run: ./run.ts). Defined apart from
 * ./flipJobs, which the worker itself imports: a worker bundle must not start its own worker.
 */
import type { FlipTasks } from './flipJobs';
import { workerFactory } from './protocol';

export const makeFlipWorker = workerFactory<FlipTasks>(
  () => new Worker(new URL('./flip.worker.ts', import.meta.url), { type: 'module' }),
);
