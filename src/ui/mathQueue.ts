/**
 * When each formula of a page is typeset (issue 15). A scene's exam page has a hundred-odd
 * formulas, most of them far below the first screen; typesetting all of them when KaTeX arrives,
 * and inserting their HTML, was about half of the main-thread blocking of a scene's load on a
 * phone. So:
 *  - a formula on or near the screen (within NEAR_MARGIN) is typeset at once, in the shared
 *    sliced queue (./chunked: short tasks that yield between slices);
 *  - the others wait for idle time (requestIdleCallback, with a timeout so a busy page still gets
 *    them), a few per idle period, in page order; one that scrolls near is promoted;
 *  - before printing, everything still waiting is typeset synchronously (`flushMathForPrint`).
 * Every formula is typeset within a few seconds of load either way: tests and find-in-page see the
 * whole page.
 */
import { runChunked } from './chunked';

type Job = () => void;

interface Entry {
  job: Job;
  el: Element | null;
  state: 'waiting' | 'idle' | 'queued' | 'done';
  cancelChunk: () => void;
}

/** How far off screen a formula still counts as "near" (typeset at once). */
export const NEAR_MARGIN = '600px';
/** Formulas typeset per idle period at most, and the idle callback's timeout (ms). */
const PER_IDLE = 3;
const IDLE_TIMEOUT_MS = 1500;

/** Every formula not typeset yet, however it waits (for the observer, idle time or its slice). */
const pending = new Set<Entry>();
const byEl = new Map<Element, Entry>();
const idle: Entry[] = [];
let idleScheduled = false;
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
  e.job();
}

function queueNow(e: Entry): void {
  if (e.state === 'queued' || e.state === 'done') return;
  if (e.state === 'idle') {
    const i = idle.indexOf(e);
    if (i >= 0) idle.splice(i, 1);
  }
  e.state = 'queued';
  e.cancelChunk = runChunked(() => run(e));
}

type IdleDeadline = { timeRemaining: () => number; didTimeout: boolean };
type RIC = (cb: (d: IdleDeadline) => void, opts?: { timeout: number }) => number;

function scheduleIdle(): void {
  if (idleScheduled || !idle.length) return;
  idleScheduled = true;
  const ric = (globalThis as { requestIdleCallback?: RIC }).requestIdleCallback;
  const tick = (d: IdleDeadline | null) => {
    idleScheduled = false;
    let k = 0;
    while (idle.length && k < PER_IDLE && (!d || d.didTimeout || d.timeRemaining() > 4)) {
      const e = idle.shift()!;
      k++;
      run(e);
    }
    scheduleIdle();
  };
  if (typeof ric === 'function') ric(tick, { timeout: IDLE_TIMEOUT_MS });
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
        if (x.isIntersecting) queueNow(e);
        else if (e.state === 'waiting') {
          e.state = 'idle';
          idle.push(e);
          scheduleIdle();
        }
      }
    },
    { rootMargin: NEAR_MARGIN },
  );
  return io;
}

/**
 * Typeset `job` soon: at once if `el` is near the screen, else in idle time. Returns a cancel
 * function (call it on unmount or when the formula changes).
 */
export function scheduleMath(el: Element | null, job: Job): () => void {
  const obs = el ? observer() : null;
  const e: Entry = { job, el, state: 'waiting', cancelChunk: () => {} };
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
}

function cancelEntry(e: Entry): void {
  if (e.state === 'done') return;
  e.cancelChunk();
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

/** Typeset everything still waiting, now (before printing). */
export function flushMathForPrint(): void {
  for (const e of [...pending]) {
    e.cancelChunk();
    run(e);
  }
  idle.length = 0;
}
