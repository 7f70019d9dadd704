/**
 * The render lab's worker, as the page starts it: one fresh worker per tile of the image
 * (src/workers/run.ts), each running render.worker.ts's `tile` task. The worker file holds the
 * tasks only, so the page's bundle never carries the renderer; this is the one factory for it.
 */
import { workerFactory } from '../../workers';
import type { RenderTasks } from './render.worker';

export const makeRenderWorker = workerFactory<RenderTasks>(
  () => new Worker(new URL('./render.worker.ts', import.meta.url), { type: 'module' }),
);
