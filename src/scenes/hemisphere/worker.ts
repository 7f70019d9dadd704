/**
 * The hemisphere scene's worker, as the page starts it (one fresh worker per run:
 * src/workers/run.ts). Defined here, not in ./jobs: the worker itself imports ./jobs, and a
 * worker whose own bundle starts that worker again is a circular worker import Vite refuses.
 */
import { workerFactory } from '../../workers';
import type { HemisphereTasks } from './hemisphere.worker';

export const makeWorker = workerFactory<HemisphereTasks>(
  () => new Worker(new URL('./hemisphere.worker.ts', import.meta.url), { type: 'module' }),
);
