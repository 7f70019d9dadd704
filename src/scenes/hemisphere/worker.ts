/** The hemisphere scene's worker, as the page starts it (one fresh worker per run: src/workers/run.ts). */
import { workerFactory } from '../../workers';
import type { HemisphereTasks } from './hemisphere.worker';

export const makeWorker = workerFactory<HemisphereTasks>(
  () => new Worker(new URL('./hemisphere.worker.ts', import.meta.url), { type: 'module' }),
);
