/**
 * Worker side of the task protocol. In a worker module:
 *
 *     exposeTasks({ integrate: async (args, progress) => { …; progress(0.5, partial); …; return result } });
 *
 * Results (and progress partials) have their typed arrays transferred, not copied.
 */
import { collectTransferables, type FromWorker, type ToWorker } from './protocol';

export type ProgressFn = (fraction: number, partial?: unknown) => void;
export type Task = (args: never, progress: ProgressFn) => unknown;

/** Yield to the worker's event loop (lets progress messages flush during long loops). */
export const yieldToEventLoop = (): Promise<void> => new Promise((r) => setTimeout(r, 0));

export function exposeTasks(tasks: Record<string, Task>): void {
  const scope = self as unknown as Worker;
  const post = (msg: FromWorker, transfer: Transferable[] = []) => scope.postMessage(msg, transfer);
  scope.onmessage = async (e: MessageEvent<ToWorker>) => {
    const { id, method, args } = e.data;
    const task = tasks[method];
    if (!task) {
      post({ id, type: 'error', message: `unknown task ${method}` });
      return;
    }
    const progress: ProgressFn = (fraction, partial) =>
      post(
        { id, type: 'progress', fraction, partial },
        partial === undefined ? [] : collectTransferables(partial),
      );
    try {
      const value = await task(args as never, progress);
      post({ id, type: 'result', value }, collectTransferables(value));
    } catch (err) {
      post({ id, type: 'error', message: err instanceof Error ? err.message : String(err) });
    }
  };
}
