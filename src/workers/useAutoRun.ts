/**
 * A worker job that starts once its panel has come near the viewport, and again whenever its key
 * changes (after `delayMs` of quiet). Panels that share a queue run one at a time (first come,
 * first served), so the workers never take every core from the page that draws their results.
 */
import type { RefObject } from 'react';
import { useSeenOnce } from '../ui/useInView';
import { useWorkerJob, type WorkerJob, type WorkerJobOptions } from './useWorkerJob';

export interface AutoRunOptions extends Omit<WorkerJobOptions, 'enabled' | 'manual'> {
  /** The panel: nothing runs before it has come within `margin` of the viewport. */
  box: RefObject<Element | null>;
  /** Default '100px'. */
  margin?: string;
}

export function useAutoRun<R, P = unknown>(
  makeWorker: () => Worker,
  method: string,
  args: unknown,
  { box, margin = '100px', delayMs = 250, ...options }: AutoRunOptions,
): WorkerJob<R, P> {
  const seen = useSeenOnce(box, margin);
  return useWorkerJob<R, P>(makeWorker, method, args, { ...options, delayMs, enabled: seen });
}
