/**
 * The Monte Carlo scene's worker, as the page starts it (one fresh worker per run:
 * src/workers/run.ts). Defined here, not in ./jobs: the worker itself imports ./jobs, and a
 * worker whose own bundle starts that worker again is a circular worker import Vite refuses.
 */
import { workerFactory } from '../../workers';
import type { McTasks } from './mc.worker';

export const makeWorker = workerFactory<McTasks>(
  () => new Worker(new URL('./mc.worker.ts', import.meta.url), { type: 'module' }),
);
