/**
 * Main-thread side: run one task in a fresh worker, with progress and cancel.
 *
 *     const ctl = new AbortController();
 *     const result = await runWorkerTask(makeWorker, 'integrate', { n: 1e7 }, { onProgress, signal: ctl.signal });
 *     ctl.abort(); // cancels: the worker is terminated at once, the promise rejects with an AbortError
 *
 * A fresh worker per task makes cancel immediate (terminate) even inside a tight loop.
 */
import { FailureError } from '../core/failure';
import type {
  ArgsOf,
  FromWorker,
  PartialOf,
  ResultOf,
  TaskMap,
  TaskName,
  ToWorker,
  WorkerFactory,
} from './protocol';

export interface RunOptions<P = unknown> {
  onProgress?: (fraction: number, partial?: P) => void;
  signal?: AbortSignal;
  /** Typed-array buffers in `args` to transfer instead of copy (the caller loses them). */
  transfer?: Transferable[];
}

export class TaskCancelled extends Error {
  constructor() {
    super('cancelled');
    this.name = 'AbortError';
  }
}

/** True for the rejection of a cancelled task (so callers can ignore it quietly). */
export function isCancelled(err: unknown): boolean {
  return err instanceof Error && err.name === 'AbortError';
}

let nextId = 1;

/**
 * Runs `method` in a fresh worker. With a typed factory (workerFactory<Tasks>) the method name, the
 * arguments, the result and the progress partials are checked against the worker's task map. A task
 * that refuses rejects with a FailureError carrying the task's `kind`; a worker that crashes, with
 * kind 'worker-failed'.
 */
export function runWorkerTask<T extends TaskMap, K extends TaskName<T>>(
  makeWorker: WorkerFactory<T>,
  method: K,
  args: ArgsOf<T, K>,
  opts: RunOptions<PartialOf<T, K>> = {},
): Promise<ResultOf<T, K>> {
  type R = ResultOf<T, K>;
  type P = PartialOf<T, K>;
  return new Promise<R>((resolve, reject) => {
    if (opts.signal?.aborted) {
      reject(new TaskCancelled());
      return;
    }
    let worker: Worker;
    try {
      worker = makeWorker();
    } catch (err) {
      reject(err instanceof Error ? err : new Error(String(err)));
      return;
    }
    const id = nextId++;
    const finish = () => {
      worker.terminate();
      opts.signal?.removeEventListener('abort', onAbort);
    };
    const onAbort = () => {
      finish();
      reject(new TaskCancelled());
    };
    opts.signal?.addEventListener('abort', onAbort);
    worker.onmessage = (e: MessageEvent<FromWorker>) => {
      const m = e.data;
      if (m.id !== id) return;
      if (m.type === 'progress') opts.onProgress?.(m.fraction, m.partial as P);
      else if (m.type === 'result') {
        finish();
        resolve(m.value as R);
      } else {
        finish();
        reject(new FailureError(m.kind, m.message));
      }
    };
    worker.onerror = (e) => {
      e.preventDefault();
      finish();
      reject(new FailureError('worker-failed', e.message || 'worker failed'));
    };
    const msg: ToWorker = { id, method, args };
    worker.postMessage(msg, opts.transfer ?? []);
  });
}
