/**
 * Worker of the render lab, tasks over the core: `tile` renders one tile of the image
 * progressively in float64 (posting each pass's sums as progress; cancel = terminate,
 * src/workers/run.ts), `inspect` runs the pixel inspector, `reference` computes the exact
 * reference image (both take long enough at large sample counts or sizes to block a page), and
 * `equalTime` renders a small image with each strategy for the same time (core/render/equalTime),
 * and `spread` renders it K times independently (core/render/expectedError); `moments` renders the
 * image with each pixel's standard error, for the comparison with the GPU renderer.
 */
import { exposeTasks, yieldToEventLoop, type ProgressFn } from '../../workers/expose';
import { renderTileJob, type TileJobArgs, type TileResult } from '../../core/render/tileJob';
import { inspectPixel, TTEST_ALPHA } from '../../core/render/inspector';
import { referenceImage } from '../../core/render/referenceImage';
import { buildScene } from '../../core/render/scene';
import { runForTime, type StrategyRun } from '../../core/render/equalTime';
import { expectedError, independentRuns } from '../../core/render/expectedError';
import {
  inspectOptions,
  type EqualTimeArgs,
  type InspectArgs,
  type MomentsArgs,
  type ReferenceArgs,
  type SpreadArgs,
  type WelchArgs,
} from './jobArgs';
import { welchOfStrategies } from '../../core/render/welchCompare';
import { makeCpuRenderer } from '../../core/render/cpuRenderer';
import { renderMoments } from '../../core/render/moments';

const tasks = {
  tile: (a: TileJobArgs, progress: ProgressFn<TileResult>) =>
    renderTileJob(a, async (r, fraction) => {
      // progress transfers its arrays, and the last pass's are also the task's result: post copies
      progress(fraction, { ...r, sum: r.sum.slice(), count: r.count.slice() });
      await yieldToEventLoop();
    }),
  moments: (a: MomentsArgs) =>
    renderMoments(
      makeCpuRenderer(buildScene(a.spec), a.view, a.res, a.res, a.trace, a.seed),
      a.res,
      a.res,
      a.spp,
    ),
  inspect: (a: InspectArgs) => inspectPixel(buildScene(a.spec), a.view, a.px[0], a.px[1], inspectOptions(a)),
  reference: (a: ReferenceArgs) => referenceImage(buildScene(a.spec), a.view, a.res, a.res, a.trace.bounces),
  spread: (a: SpreadArgs) => {
    const scene = buildScene(a.spec);
    const reference = referenceImage(scene, a.view, a.res, a.res, a.trace.bounces);
    const runs = independentRuns(scene, a.view, a.res, a.trace, a.seed, a.runs, a.spp);
    return expectedError(runs, reference.values);
  },
  welch: (a: WelchArgs) =>
    welchOfStrategies(
      buildScene(a.spec),
      a.view,
      a.res,
      a.trace,
      a.other,
      a.seed,
      a.runs,
      a.spp,
      TTEST_ALPHA,
    ),
  equalTime: async (a: EqualTimeArgs, progress: ProgressFn<{ finished: number }>) => {
    const scene = buildScene(a.spec);
    const reference = referenceImage(scene, a.view, a.res, a.res, a.trace.bounces);
    // one small untimed pass of every strategy first, so that none is timed while its code is
    // still being compiled (the first would otherwise pay for the warm-up of all of them)
    const small = referenceImage(scene, a.view, 8, 8, a.trace.bounces).values;
    for (const strategy of a.strategies)
      runForTime(scene, a.view, 8, { ...a.trace, strategy }, a.seed, small, 0, () => 0);
    const runs: StrategyRun[] = [];
    for (const strategy of a.strategies) {
      const trace = { ...a.trace, strategy };
      runs.push(
        runForTime(scene, a.view, a.res, trace, a.seed, reference.values, a.budgetMs, () =>
          performance.now(),
        ),
      );
      // (progress transfers the buffers it carries, and the runs' images are still needed: a count only)
      progress(runs.length / a.strategies.length, { finished: runs.length });
      await yieldToEventLoop();
    }
    return { runs, reference: reference.values, exact: reference.exact };
  },
};
exposeTasks(tasks);

/** The worker's tasks, for workerFactory<RenderTasks> on the page's side. */
export type RenderTasks = typeof tasks;
