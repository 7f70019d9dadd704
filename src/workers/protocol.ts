/** Messages between {@link runWorkerTask} and {@link exposeTasks}, and the types of a task map. */
import type { Failure } from '../core/failure';

export type ToWorker = { id: number; method: string; args: unknown };
export type FromWorker =
  | { id: number; type: 'progress'; fraction: number; partial?: unknown }
  | { id: number; type: 'result'; value: unknown }
  | ({ id: number; type: 'error' } & Pick<Failure, 'kind' | 'message'>);

/** Reports progress from inside a task: a fraction in [0, 1] and, optionally, a partial result. */
export type ProgressFn<P = unknown> = (fraction: number, partial?: P) => void;

/**
 * The tasks a worker offers, by name: `(args, progress) => result` (or a promise of one). A worker
 * module builds one (`const tasks = { … }`), passes it to exposeTasks and exports its type, which
 * the page's side names in workerFactory<typeof tasks>: task names, arguments, results and
 * progress partials are then checked at compile time across the worker boundary.
 */
// `never` in the argument positions lets every concrete task fit the map (function parameters are
// contravariant, and `never` is assignable to every type); the concrete types come back through
// ArgsOf / ResultOf / PartialOf, which read them from the task itself.
export type TaskMap = { [name: string]: (args: never, progress: never) => unknown };

export type TaskName<T extends TaskMap> = keyof T & string;
export type ArgsOf<T extends TaskMap, K extends TaskName<T>> = Parameters<T[K]>[0];
export type ResultOf<T extends TaskMap, K extends TaskName<T>> = Awaited<ReturnType<T[K]>>;
export type PartialOf<T extends TaskMap, K extends TaskName<T>> = Parameters<T[K]>[1] extends
  ProgressFn<infer P> | undefined
  ? P
  : never;

/** Starts a worker whose tasks are T (the type lives only at compile time). */
export type WorkerFactory<T extends TaskMap = TaskMap> = (() => Worker) & { readonly __tasks?: T };

/** Names the task map of a worker factory: `workerFactory<McTasks>(() => new Worker(…))`. */
export function workerFactory<T extends TaskMap>(make: () => Worker): WorkerFactory<T> {
  return make as WorkerFactory<T>;
}

/** Typed-array buffers inside a value (one level of objects/arrays deep, plus the value itself). */
export function collectTransferables(value: unknown, out: Transferable[] = [], depth = 0): Transferable[] {
  if (value === null || typeof value !== 'object' || depth > 3) return out;
  if (ArrayBuffer.isView(value)) {
    const buf = value.buffer;
    if (buf instanceof ArrayBuffer && !out.includes(buf)) out.push(buf);
    return out;
  }
  if (value instanceof ArrayBuffer) {
    if (!out.includes(value)) out.push(value);
    return out;
  }
  const items = Array.isArray(value) ? value : Object.values(value as Record<string, unknown>);
  for (const v of items) collectTransferables(v, out, depth + 1);
  return out;
}
