export { runWorkerTask, isCancelled, TaskCancelled, type RunOptions } from './run';
export { useWorkerJob, type WorkerJob, type WorkerJobOptions } from './useWorkerJob';
export { useAutoRun, type AutoRunOptions } from './useAutoRun';
