/**
 * Worker of the render lab, three tasks over the core: `tile` renders one tile of the image
 * progressively in float64 (posting each pass's sums as progress; cancel = terminate,
 * src/workers/run.ts), `inspect` runs the pixel inspector, and `reference` computes the exact
 * reference image (both take long enough at large sample counts or sizes to block a page).
 */
import { exposeTasks, yieldToEventLoop, type ProgressFn } from '../../workers/expose';
import { renderTileJob, type TileJobArgs, type TileResult } from '../../core/render/tileJob';
import { inspectPixel } from '../../core/render/inspector';
import { referenceImage } from '../../core/render/referenceImage';
import { buildScene } from '../../core/render/scene';
import { inspectOptions, type InspectArgs, type ReferenceArgs } from './jobArgs';

const tasks = {
  tile: (a: TileJobArgs, progress: ProgressFn<TileResult>) =>
    renderTileJob(a, async (r, fraction) => {
      // progress transfers its arrays, and the last pass's are also the task's result: post copies
      progress(fraction, { ...r, sum: r.sum.slice(), count: r.count.slice() });
      await yieldToEventLoop();
    }),
  inspect: (a: InspectArgs) => inspectPixel(buildScene(a.spec), a.view, a.px[0], a.px[1], inspectOptions(a)),
  reference: (a: ReferenceArgs) => referenceImage(buildScene(a.spec), a.view, a.res, a.res, a.trace.bounces),
};
exposeTasks(tasks);

/** The worker's tasks, for workerFactory<RenderTasks> on the page's side. */
export type RenderTasks = typeof tasks;
