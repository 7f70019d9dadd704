/**
 * The render lab's worker, as the page starts it: one fresh worker per tile of the image
 * (src/workers/run.ts), each running render.worker.ts's `tile` task. The worker file holds the
 * tasks only, so the page's bundle never carries the renderer; this is the one factory for it, and
 * beside it the one for the GPU renderer's worker.
 */
import { workerFactory } from '../../workers';
import type { RenderTasks } from './render.worker';

export const makeRenderWorker = workerFactory<RenderTasks>(
  () => new Worker(new URL('./render.worker.ts', import.meta.url), { type: 'module' }),
);

/** The GPU renderer's worker (./gpu/gpu.worker.ts): it owns the WebGL2 context, on an OffscreenCanvas. */
export function makeGpuWorker(): Worker {
  return new Worker(new URL('./gpu/gpu.worker.ts', import.meta.url), { type: 'module' });
}
