export { runWorkerTask, isCancelled, TaskCancelled, type RunOptions } from './run';
export { useWorkerTask, type WorkerTaskState } from './useWorkerTask';
