/**
 * Work that belongs to an element of the page, done when the element is about to be seen, else in
 * idle time. Two users: formulas (./mathQueue: KaTeX typesetting) and the exam page's
 * sections below the first screen (./Deferred: their React subtree is mounted late). A scene's
 * exam page is long; doing all of it when the page opens was most of its main-thread blocking on a
 * phone. So, per queue:
 *  - a job whose element is on or near the screen (within `margin`) runs at once, through
 *    `runNear` (e.g. the shared sliced queue of ./chunked);
 *  - the others wait for idle time (requestIdleCallback, with a timeout so a busy page still gets
 *    them), and first for `idleAfter` where given (the page's opening to be over), `perIdle` per
 *    idle period, in the order they were scheduled (page order); one that scrolls near is promoted;
 *  - `flush()` runs everything still waiting, synchronously (before printing).
 * Every job runs within a few seconds of load either way: tests and find-in-page see the whole page.
 */

/** A job; `rect` is the element's box as the observer last reported it (read without a layout), if it did. */
type Job = (rect?: DOMRectReadOnly) => void;

interface Entry {
  job: Job;
  el: Element | null;
  rect?: DOMRectReadOnly;
  state: 'waiting' | 'idle' | 'queued' | 'done';
  cancelNear: () => void;
}

export interface ViewQueueOptions {
  /** How far off screen an element still counts as near (IntersectionObserver rootMargin). */
  margin: string;
  /** Jobs run per idle period at most. */
  perIdle: number;
  /** The idle callback's timeout (ms): a page that is never idle still gets its jobs. */
  idleTimeoutMs: number;
  /** How a near job runs: given the job, starts it (now or soon) and returns a cancel function. */
  runNear: (job: () => void) => () => void;
  /**
   * Idle-time jobs wait for this promise first (near jobs never do). Without it they start at
   * the first idle period, which on a loading page comes between its own frames.
   */
  idleAfter?: () => Promise<void>;
}

export interface ViewQueue {
  /** Run `job` soon: at once if `el` is near the screen, else in idle time. Returns a cancel function. */
  schedule: (el: Element | null, job: Job) => () => void;
  /** Run everything still waiting, now. */
  flush: () => void;
}

type IdleDeadline = { timeRemaining: () => number; didTimeout: boolean };
type RIC = (cb: (d: IdleDeadline) => void, opts?: { timeout: number }) => number;

export function createViewQueue({
  margin,
  perIdle,
  idleTimeoutMs,
  runNear,
  idleAfter,
}: ViewQueueOptions): ViewQueue {
  /** Every job not run yet, however it waits (for the observer, idle time or its near slot). */
  const pending = new Set<Entry>();
  const byEl = new Map<Element, Entry>();
  const idle: Entry[] = [];
  let idleScheduled = false;
  /** Whether idle-time jobs may run (`idleAfter` has resolved, or there is none). */
  let idleOpen = !idleAfter;
  let idleOpening = false;
  let io: IntersectionObserver | null = null;
  /** Elements the observer has reported near the screen (kept up to date while observed). */
  const near = new WeakSet<Element>();

  function run(e: Entry): void {
    if (e.state === 'done') return;
    e.state = 'done';
    pending.delete(e);
    if (e.el) {
      byEl.delete(e.el);
      io?.unobserve(e.el);
    }
    e.job(e.rect);
  }

  function queueNow(e: Entry): void {
    if (e.state === 'queued' || e.state === 'done') return;
    if (e.state === 'idle') {
      const i = idle.indexOf(e);
      if (i >= 0) idle.splice(i, 1);
    }
    e.state = 'queued';
    e.cancelNear = runNear(() => run(e));
  }

  function scheduleIdle(): void {
    if (idleScheduled || !idle.length) return;
    if (!idleOpen) {
      if (!idleOpening && idleAfter) {
        idleOpening = true;
        const open = () => {
          idleOpen = true;
          scheduleIdle();
        };
        idleAfter().then(open, open);
      }
      return;
    }
    idleScheduled = true;
    const ric = (globalThis as { requestIdleCallback?: RIC }).requestIdleCallback;
    const tick = (d: IdleDeadline | null) => {
      idleScheduled = false;
      let k = 0;
      while (idle.length && k < perIdle && (!d || d.didTimeout || d.timeRemaining() > 4)) {
        const e = idle.shift()!;
        k++;
        run(e);
      }
      scheduleIdle();
    };
    if (typeof ric === 'function') ric(tick, { timeout: idleTimeoutMs });
    else setTimeout(() => tick(null), 50);
  }

  function observer(): IntersectionObserver | null {
    if (io || typeof IntersectionObserver !== 'function') return io;
    io = new IntersectionObserver(
      (entries) => {
        for (const x of entries) {
          if (x.isIntersecting) near.add(x.target);
          else near.delete(x.target);
          const e = byEl.get(x.target);
          if (!e) continue;
          e.rect = x.boundingClientRect;
          if (x.isIntersecting) queueNow(e);
          else if (e.state === 'waiting') {
            e.state = 'idle';
            idle.push(e);
            scheduleIdle();
          }
        }
      },
      { rootMargin: margin },
    );
    return io;
  }

  function cancelEntry(e: Entry): void {
    if (e.state === 'done') return;
    e.cancelNear();
    if (e.state === 'idle') {
      const i = idle.indexOf(e);
      if (i >= 0) idle.splice(i, 1);
    }
    e.state = 'done';
    pending.delete(e);
    if (e.el && byEl.get(e.el) === e) {
      byEl.delete(e.el);
      io?.unobserve(e.el);
    }
  }

  return {
    schedule(el, job) {
      const obs = el ? observer() : null;
      const e: Entry = { job, el, state: 'waiting', cancelNear: () => {} };
      pending.add(e);
      if (!el || !obs) {
        queueNow(e);
      } else if (near.has(el)) {
        // already known to be on screen (a formula whose live numbers changed): no wait for the observer
        queueNow(e);
      } else {
        const old = byEl.get(el);
        if (old) cancelEntry(old);
        byEl.set(el, e);
        obs.observe(el); // the observer reports the first state asynchronously
      }
      return () => cancelEntry(e);
    },
    flush() {
      for (const e of [...pending]) {
        e.cancelNear();
        run(e);
      }
      idle.length = 0;
    },
  };
}
