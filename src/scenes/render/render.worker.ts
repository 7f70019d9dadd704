/**
 * Worker of the render lab: renders one tile of the image progressively in float64 with the
 * core's CPU renderer, posting each pass's sums as progress (cancel = terminate, src/workers/run.ts).
 */
import { exposeTasks, yieldToEventLoop, type ProgressFn } from '../../workers/expose';
import { renderTileJob, type TileJobArgs, type TileResult } from '../../core/render/tileJob';

const tasks = {
  tile: (a: TileJobArgs, progress: ProgressFn<TileResult>) =>
    renderTileJob(a, async (r, fraction) => {
      progress(fraction, r);
      await yieldToEventLoop();
    }),
};
exposeTasks(tasks);

/** The worker's tasks, for workerFactory<RenderTasks> on the page's side. */
export type RenderTasks = typeof tasks;
