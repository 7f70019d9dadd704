/**
 * Small main-thread jobs run in short slices that yield to the browser in between, so that a burst
 * of them (every formula of a scene when KaTeX arrives, an image computed row by row) never makes
 * one long task: input and paint get their turn every {@link SLICE_MS} ms.
 *
 * Lighthouse's mobile preset counts a task as blocking above 50 ms after a 4× CPU slowdown, so a
 * slice must stay under ~12 ms on a desktop; 8 ms leaves room for the job that overruns it.
 */

/** Longest slice of queued jobs before yielding (ms). */
export const SLICE_MS = 8;

type Job = () => void;
const queue: Job[] = [];
let scheduled = false;

interface PostTaskScheduler {
  postTask: (
    cb: () => void,
    opts?: { priority?: 'user-blocking' | 'user-visible' | 'background' },
  ) => Promise<unknown>;
}

/** Run `fn` in a new task soon (scheduler.postTask, else a MessageChannel message, else setTimeout). */
export function nextTask(fn: () => void): void {
  const s = (globalThis as { scheduler?: Partial<PostTaskScheduler> }).scheduler;
  if (s && typeof s.postTask === 'function') {
    s.postTask(fn, { priority: 'user-visible' }).catch(() => {});
    return;
  }
  if (typeof MessageChannel === 'function') {
    const ch = new MessageChannel();
    ch.port1.onmessage = () => {
      ch.port1.close();
      fn();
    };
    ch.port2.postMessage(null);
    return;
  }
  setTimeout(fn, 0);
}

function drain(): void {
  scheduled = false;
  const t0 = performance.now();
  while (queue.length) {
    const job = queue.shift()!;
    try {
      job();
    } catch (e) {
      // a failing job must not stop the others; report it the way an uncaught error would be
      setTimeout(() => {
        throw e;
      });
    }
    if (performance.now() - t0 >= SLICE_MS) break;
  }
  if (queue.length && !scheduled) {
    scheduled = true;
    nextTask(drain);
  }
}

/**
 * Queue a small job (a few ms at most) to run in a later task, in order, sliced with the other
 * queued jobs. Returns a function that cancels it if it has not run yet.
 */
export function runChunked(job: Job): () => void {
  let cancelled = false;
  const wrapped = () => {
    if (!cancelled) job();
  };
  queue.push(wrapped);
  if (!scheduled) {
    scheduled = true;
    nextTask(drain);
  }
  return () => {
    cancelled = true;
  };
}
