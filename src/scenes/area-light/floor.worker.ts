/** Worker of #/area-light: runs ./jobs off the main thread (cancel = terminate, src/workers/run.ts). */
import { exposeTasks } from '../../workers/expose';
import { convergenceJob, estimatesJob, renderJob, timingJob } from './jobs';

const tasks = { convergence: convergenceJob, estimates: estimatesJob, render: renderJob, timing: timingJob };
exposeTasks(tasks);

/** The worker's tasks, for workerFactory<AreaLightTasks> on the page's side. */
export type AreaLightTasks = typeof tasks;
