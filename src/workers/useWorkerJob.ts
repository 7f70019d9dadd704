/**
 * The one way a scene runs a long computation: `useWorkerJob(makeWorker, method, args, options)`.
 *
 *     const makeWorker = workerFactory<HemisphereTasks>(() => new Worker(new URL(…), { type: 'module' }));
 *     const stats = useWorkerJob(makeWorker, 'stats', args, { delayMs: 60 });
 *     stats.result   // the result for THESE args, or undefined while it is computed (never a stale one)
 *     stats.error    // a Failure ({ kind, message }) when the task refused or the worker failed
 *
 * The task name, its arguments, its result and its progress partials are checked against the
 * worker's task map (./protocol TaskMap) at compile time.
 *
 * - When the arguments change (by `key`, default `JSON.stringify(args)`) the run in flight is
 *   cancelled (its worker terminated) and, after `delayMs` of quiet (debounce), a new one starts.
 * - `enabled: false` cancels and starts nothing; `manual: true` starts only on `run()`;
 *   `afterSettle: true` holds the opening run until the page has loaded (`waiting` meanwhile).
 * - `queue: 'name'` runs the jobs of every hook on that queue one at a time, first come first
 *   served (so background runs never take every core from the page that draws their results).
 * - Progress (fraction and partial results) is coalesced to one React update per animation frame.
 * - Unmounting cancels. `cancel()` stops the run; `run()` (re)starts it for the current args.
 *
 * The worker side is `exposeTasks` (./expose.ts) over plain-data job functions (a scene's jobs.ts).
 */
import {
  startTransition,
  useCallback,
  useEffect,
  useId,
  useRef,
  useState,
  useSyncExternalStore,
} from 'react';
import { asFailure, type Failure } from '../core/failure';
import type { ArgsOf, PartialOf, ResultOf, TaskMap, TaskName, WorkerFactory } from './protocol';
import { isCancelled, runWorkerTask } from './run';
import { usePageSettled } from '../ui/useOpeningDone';

export interface WorkerJobOptions {
  /** Identity of the arguments (default JSON.stringify(args)). A new key cancels and restarts. */
  key?: string;
  /** false: cancel any run and start none (default true). */
  enabled?: boolean;
  /** Quiet time after the last change before a run starts, in ms (default 0). */
  delayMs?: number;
  /** Name of a queue: the jobs of all hooks on one queue run one at a time, in order of asking. */
  queue?: string;
  /** true: never start by itself, only on run() (a change still cancels and clears). */
  manual?: boolean;
  /**
   * true: the run for the arguments the scene opened with waits until the page has settled
   * (../ui/whenQuiet pageSettled: first screen painted, then quiet; 3 s at most), for a result
   * that is not on the first screen. A change of arguments before then runs as usual.
   */
  afterSettle?: boolean;
}

export interface WorkerJob<R, P> {
  /** The result for the current arguments (undefined until it arrives). */
  result: R | undefined;
  /** The latest partial result of the run for the current arguments. */
  partial: P | undefined;
  running: boolean;
  /** Asked for, but waiting for its turn on the queue. */
  waiting: boolean;
  progress: number;
  /** Why the run failed (the task's own Failure kind, or 'worker-failed'); null otherwise. */
  error: Failure | null;
  /** (Re)start now for the current arguments (after its turn on the queue). */
  run: () => void;
  cancel: () => void;
}

// ---- queues: one owner at a time, waiters in order -------------------------------------------
interface Queue {
  owner: string | null;
  waiting: string[];
  listeners: Set<() => void>;
}
const queues = new Map<string, Queue>();
function queueOf(name: string): Queue {
  let q = queues.get(name);
  if (!q) {
    q = { owner: null, waiting: [], listeners: new Set() };
    queues.set(name, q);
  }
  return q;
}
const notify = (q: Queue) => {
  for (const l of q.listeners) l();
};
/** Take the queue if it is free (or ours) and we are first in line; else join the line. */
function acquire(q: Queue, id: string): boolean {
  if (q.owner === id) return true;
  if (q.owner === null && (q.waiting.length === 0 || q.waiting[0] === id)) {
    q.owner = id;
    q.waiting = q.waiting.filter((w) => w !== id);
    notify(q);
    return true;
  }
  if (!q.waiting.includes(id)) q.waiting.push(id);
  return false;
}
function release(q: Queue, id: string): void {
  const before = q.waiting.length;
  q.waiting = q.waiting.filter((w) => w !== id);
  if (q.owner === id) q.owner = null;
  else if (q.waiting.length === before) return;
  notify(q);
}
const NO_QUEUE = (): (() => void) => () => {};

interface JobState<R, P> {
  key: string | null;
  running: boolean;
  progress: number;
  partial: P | undefined;
  result: R | undefined;
  error: Failure | null;
}
const IDLE: JobState<never, never> = {
  key: null,
  running: false,
  progress: 0,
  partial: undefined,
  result: undefined,
  error: null,
};

export function useWorkerJob<T extends TaskMap, K extends TaskName<T>>(
  makeWorker: WorkerFactory<T>,
  method: K,
  args: ArgsOf<T, K> | null,
  options: WorkerJobOptions = {},
): WorkerJob<ResultOf<T, K>, PartialOf<T, K>> {
  type R = ResultOf<T, K>;
  type P = PartialOf<T, K>;
  const { enabled: asked = true, delayMs = 0, queue, manual = false, afterSettle = false } = options;
  // null arguments: nothing to run (as enabled: false)
  const enabled = asked && args !== null;
  const key = options.key ?? JSON.stringify(args);
  // the arguments the scene opened with (null once they have changed: no later run is held)
  const openingKey = useRef<string | null>(key);
  const settled = usePageSettled(afterSettle);
  const held = !settled && key === openingKey.current;
  useEffect(() => {
    if (key !== openingKey.current) openingKey.current = null;
  }, [key]);
  const id = useId();
  const [state, setState] = useState<JobState<R, P>>(IDLE);
  /** A run asked for (its key and a serial so run() can ask again for the same key). */
  const [wanted, setWanted] = useState<{ key: string; serial: number } | null>(null);
  const ctl = useRef<AbortController | null>(null);
  const raf = useRef(0);
  const latest = useRef({ args, key, makeWorker });
  useEffect(() => {
    latest.current = { args, key, makeWorker };
  });
  const serial = useRef(0);

  const q = queue ? queueOf(queue) : null;
  const subscribe = useCallback(
    (l: () => void) => {
      if (!q) return NO_QUEUE();
      q.listeners.add(l);
      return () => void q.listeners.delete(l);
    },
    [q],
  );
  const owner = useSyncExternalStore(
    subscribe,
    () => q?.owner ?? null,
    () => null,
  );

  const stop = useCallback(() => {
    ctl.current?.abort();
    ctl.current = null;
    if (raf.current) cancelAnimationFrame(raf.current);
    raf.current = 0;
    if (q) release(q, id);
    setState((s) => (s.running ? { ...s, running: false } : s));
  }, [q, id]);

  // a change of arguments cancels the run in flight, then asks for a new one after the delay
  useEffect(() => {
    stop();
    setWanted(null);
    if (!enabled || manual || held) return;
    const t = setTimeout(() => setWanted({ key, serial: ++serial.current }), delayMs);
    return () => clearTimeout(t);
  }, [key, enabled, manual, held, delayMs, stop]);

  // start what is asked for when its turn comes
  useEffect(() => {
    if (!wanted || wanted.key !== key) return;
    if (q && !acquire(q, id)) return; // retried when the queue's owner changes
    setWanted(null);
    ctl.current?.abort();
    const c = new AbortController();
    ctl.current = c;
    const runKey = key;
    setState({ key: runKey, running: true, progress: 0, partial: undefined, result: undefined, error: null });
    let pending: { fraction: number; partial?: P } | null = null;
    const settle = (patch: Partial<JobState<R, P>>) => {
      if (ctl.current !== c) return;
      ctl.current = null;
      if (q) release(q, id);
      // a transition: a result re-renders most of a scene, which React then does in slices that
      // yield instead of one long task
      startTransition(() => setState((s) => (s.key === runKey ? { ...s, ...patch, running: false } : s)));
    };
    runWorkerTask(latest.current.makeWorker, method, latest.current.args as ArgsOf<T, K>, {
      signal: c.signal,
      onProgress: (fraction, partial) => {
        pending = { fraction, partial };
        if (raf.current) return;
        raf.current = requestAnimationFrame(() => {
          raf.current = 0;
          const p = pending;
          pending = null;
          if (p && ctl.current === c)
            startTransition(() =>
              setState((s) =>
                s.key === runKey ? { ...s, progress: p.fraction, partial: p.partial ?? s.partial } : s,
              ),
            );
        });
      },
    }).then(
      (result) => settle({ progress: 1, result }),
      (err) => {
        if (!isCancelled(err)) settle({ error: asFailure(err) });
      },
    );
  }, [wanted, key, owner, q, id, method]);

  useEffect(() => stop, [stop]);

  const run = useCallback(() => setWanted({ key: latest.current.key, serial: ++serial.current }), []);
  const cancel = useCallback(() => {
    stop();
    setWanted(null);
  }, [stop]);

  const current = state.key === key;
  const running = current && state.running;
  return {
    result: current ? state.result : undefined,
    partial: current ? state.partial : undefined,
    running,
    waiting:
      (!running && wanted !== null && wanted.key === key && !!q && owner !== null && owner !== id) ||
      (held && enabled && !manual),
    progress: current ? state.progress : 0,
    error: current ? state.error : null,
    run,
    cancel,
  };
}
