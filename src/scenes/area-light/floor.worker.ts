/** Worker of #/area-light: runs ./jobs off the main thread (cancel = terminate, src/workers/run.ts). */
import { exposeTasks } from '../../workers/expose';
import { convergenceJob, estimatesJob, renderJob, timingJob } from './jobs';

exposeTasks({
  convergence: (args: Parameters<typeof convergenceJob>[0], progress) => convergenceJob(args, progress),
  estimates: (args: Parameters<typeof estimatesJob>[0], progress) => estimatesJob(args, progress),
  render: (job: Parameters<typeof renderJob>[0], progress) => renderJob(job, progress),
  timing: (args: Parameters<typeof timingJob>[0], progress) => timingJob(args, progress),
});
