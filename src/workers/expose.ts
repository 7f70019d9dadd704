/**
 * Worker side of the task protocol. In a worker module:
 *
 *     const tasks = { integrate: async (args: IntegrateArgs, progress: ProgressFn<Partial>) => { …; return result } };
 *     exposeTasks(tasks);
 *     export type IntegrateTasks = typeof tasks;   // for workerFactory<IntegrateTasks> on the page's side
 *
 * Results (and progress partials) have their typed arrays transferred, not copied. A task refuses
 * with a Failure by throwing it (`raise(fail('bad-pdf', '…'))`, core/failure): its `kind` and
 * `message` cross to the page, where the run rejects with a FailureError of the same kind.
 */
import { asFailure } from '../core/failure';
import { collectTransferables, type FromWorker, type TaskMap, type ToWorker } from './protocol';

export type { ProgressFn, TaskMap } from './protocol';

/** Yield to the worker's event loop (lets progress messages flush during long loops). */
export const yieldToEventLoop = (): Promise<void> => new Promise((r) => setTimeout(r, 0));

export function exposeTasks<T extends TaskMap>(tasks: T): void {
  const scope = self as unknown as Worker;
  const post = (msg: FromWorker, transfer: Transferable[] = []) => scope.postMessage(msg, transfer);
  scope.onmessage = async (e: MessageEvent<ToWorker>) => {
    const { id, method, args } = e.data;
    const task = Object.hasOwn(tasks, method) ? tasks[method] : undefined;
    if (!task) {
      post({ id, type: 'error', kind: 'unknown-task', message: `unknown task ${method}` });
      return;
    }
    const progress = (fraction: number, partial?: unknown) =>
      post(
        { id, type: 'progress', fraction, partial },
        partial === undefined ? [] : collectTransferables(partial),
      );
    try {
      // the map's type checks each task's arguments at the call site on the page; here they arrive
      // as posted, untyped, and are handed on as they are
      const value = await (task as (a: unknown, p: typeof progress) => unknown)(args, progress);
      post({ id, type: 'result', value }, collectTransferables(value));
    } catch (err) {
      const f = asFailure(err);
      post({ id, type: 'error', kind: f.kind, message: f.message });
    }
  };
}
