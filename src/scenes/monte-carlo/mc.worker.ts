/**
 * Worker of the Monte Carlo scene: convergence runs, RMSE over independent runs (with timing),
 * the unbiasedness histogram, and large single estimates, off the main thread with progress.
 * Cancel = the page terminates the worker (src/workers/run.ts).
 */
import { exposeTasks, type ProgressFn } from '../../workers/expose';
import { compileX } from './expr';
import { convergenceJob, estimateJob, histogramJob, rmseJob } from './jobs';

type Args<F extends (a: never, ...r: never[]) => unknown> = Parameters<F>[0];
type Progress<F extends (a: never, c: never, p: never) => unknown> = NonNullable<Parameters<F>[2]>;

const tasks = {
  convergence: (args: Args<typeof convergenceJob>, progress: Progress<typeof convergenceJob>) =>
    convergenceJob(args, compileX, progress),
  rmse: (args: Args<typeof rmseJob>, progress: Progress<typeof rmseJob>) => rmseJob(args, compileX, progress),
  histogram: (args: Args<typeof histogramJob>, progress: Progress<typeof histogramJob>) =>
    histogramJob(args, compileX, progress),
  estimate: (args: Args<typeof estimateJob>, progress: ProgressFn) => estimateJob(args, compileX, progress),
};
exposeTasks(tasks);

/** The worker's tasks, for workerFactory<McTasks> on the page's side. */
export type McTasks = typeof tasks;
