/**
 * Worker of the Monte Carlo scene: convergence runs, RMSE over independent runs (with timing),
 * the unbiasedness histogram, and large single estimates, off the main thread with progress.
 * Cancel = the page terminates the worker (src/workers/run.ts).
 */
import { exposeTasks } from '../../workers/expose';
import { compileX } from './expr';
import { convergenceJob, estimateJob, histogramJob, rmseJob } from './jobs';

exposeTasks({
  convergence: (args: Parameters<typeof convergenceJob>[0], progress) =>
    convergenceJob(args, compileX, progress),
  rmse: (args: Parameters<typeof rmseJob>[0], progress) => rmseJob(args, compileX, progress),
  histogram: (args: Parameters<typeof histogramJob>[0], progress) => histogramJob(args, compileX, progress),
  estimate: (args: Parameters<typeof estimateJob>[0], progress) => estimateJob(args, compileX, progress),
});
