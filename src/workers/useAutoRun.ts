/**
 * A worker job that starts once its panel has come near the viewport, and again whenever its key
 * changes (after `delayMs` of quiet). Panels that share a queue run one at a time (first come,
 * first served), so the workers never take every core from the page that draws their results.
 */
import type { RefObject } from 'react';
import { useSeenOnce } from '../ui/useInView';
import type { ArgsOf, PartialOf, ResultOf, TaskMap, TaskName, WorkerFactory } from './protocol';
import { useWorkerJob, type WorkerJob, type WorkerJobOptions } from './useWorkerJob';

export interface AutoRunOptions extends Omit<WorkerJobOptions, 'enabled' | 'manual'> {
  /** The panel: nothing runs before it has come within `margin` of the viewport. */
  box: RefObject<Element | null>;
  /** Default '100px'. */
  margin?: string;
}

export function useAutoRun<T extends TaskMap, K extends TaskName<T>>(
  makeWorker: WorkerFactory<T>,
  method: K,
  args: ArgsOf<T, K> | null,
  { box, margin = '100px', delayMs = 250, ...options }: AutoRunOptions,
): WorkerJob<ResultOf<T, K>, PartialOf<T, K>> {
  const seen = useSeenOnce(box, margin);
  return useWorkerJob(makeWorker, method, args, { ...options, delayMs, enabled: seen });
}
