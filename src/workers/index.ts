export { runWorkerTask, isCancelled, TaskCancelled, type RunOptions } from './run';
export { useWorkerJob, type WorkerJob, type WorkerJobOptions } from './useWorkerJob';
export { workerFactory, type WorkerFactory, type TaskMap, type ProgressFn } from './protocol';
export { useAutoRun, type AutoRunOptions } from './useAutoRun';
