/**
 * Resolves once the page has been idle for a while: `quietMs` of idle periods in a row, each a
 * whole one (requestIdleCallback's deadline has ≥ {@link FULL_IDLE_MS} ms left, so nothing else was
 * queued), or after `maxMs` whatever happens. A gap between idle callbacks (a task ran) starts the
 * count again.
 *
 * Used to register the service worker: its install downloads and stores the whole build
 * (every scene, three.js, KaTeX's fonts), about a second of CPU on a worker thread. Started
 * while a scene is still mounting its sections, it took the second core from the page on a phone
 * and stretched the page's own tasks several times over.
 */

import { afterPaint } from './afterPaint';

/** An idle period with at least this much time left is a whole one (the browser caps them at 50 ms). */
export const FULL_IDLE_MS = 40;

export interface IdleApi {
  request: (
    cb: (deadline: { timeRemaining: () => number; didTimeout: boolean }) => void,
    opts: { timeout: number },
  ) => unknown;
  now: () => number;
  setTimeout: (cb: () => void, ms: number) => unknown;
}

function browserIdle(): IdleApi {
  const ric = typeof requestIdleCallback === 'function' ? requestIdleCallback : null;
  return {
    request: (cb, opts) =>
      ric ? ric(cb, opts) : setTimeout(() => cb({ timeRemaining: () => 50, didTimeout: false }), 100),
    now: () => performance.now(),
    setTimeout: (cb, ms) => setTimeout(cb, ms),
  };
}

export function whenQuiet({
  quietMs = 2000,
  maxMs = 30_000,
  api = browserIdle(),
}: { quietMs?: number; maxMs?: number; api?: IdleApi } = {}): Promise<void> {
  return new Promise((resolve) => {
    let done = false;
    const finish = () => {
      if (done) return;
      done = true;
      resolve();
    };
    api.setTimeout(finish, maxMs);
    let since: number | null = null; // start of the current run of whole idle periods
    let last = api.now();
    const tick = (deadline: { timeRemaining: () => number; didTimeout: boolean }) => {
      if (done) return;
      const now = api.now();
      const whole = !deadline.didTimeout && deadline.timeRemaining() >= FULL_IDLE_MS;
      // consecutive idle periods follow each other closely; a long gap means a task ran in between
      if (!whole || now - last > 120) since = null;
      else if (since === null) since = now;
      last = now;
      if (since !== null && now - since >= quietMs) {
        finish();
        return;
      }
      api.request(tick, { timeout: 1000 });
    };
    api.request(tick, { timeout: 1000 });
  });
}

let settled: Promise<void> | null = null;
let settledNow = false;

/**
 * Once per page: resolves when the first screen has been painted and the page has then been quiet
 * for half a second (3 s at most). A scene's opening computation whose result is not on the first
 * screen waits for it (useWorkerJob's `afterSettle`): started while the page mounts its sections
 * and typesets its formulas, a worker takes a core from it and stretches every task.
 */
export function pageSettled(): Promise<void> {
  if (!settled) {
    settled = afterPaint()
      .then(() => whenQuiet({ quietMs: 500, maxMs: 3000 }))
      .then(() => {
        settledNow = true;
        // for tests and tools that measure a loaded page
        if (typeof document !== 'undefined') document.documentElement.setAttribute('data-settled', '');
      });
  }
  return settled;
}

/** Whether {@link pageSettled} has resolved. */
export function isPageSettled(): boolean {
  return settledNow;
}

/** The events by which a reader acts on the page: a key, a press, the wheel, a touch. */
export const READER_EVENTS = ['keydown', 'pointerdown', 'wheel', 'touchstart'] as const;

let acted: Promise<void> | null = null;
let actedNow = false;

/** Once per page: resolves at the reader's first key, press, wheel or touch. */
export function readerActed(): Promise<void> {
  if (!acted) {
    acted = new Promise<void>((resolve) => {
      if (typeof window === 'undefined') return;
      const done = () => {
        for (const t of READER_EVENTS) window.removeEventListener(t, done, true);
        actedNow = true;
        resolve();
      };
      for (const t of READER_EVENTS) window.addEventListener(t, done, { capture: true, passive: true });
    });
  }
  return acted;
}

/**
 * Once per page: resolves when the opening is over, i.e. the page has settled ({@link pageSettled})
 * or the reader has acted ({@link readerActed}), whichever comes first. The work that belongs to
 * the page far below the screen (its sections mounted late, its formulas typeset) waits for it:
 * done in the idle moments between the opening's own frames, it took the second core from the
 * opening on a phone and stretched the opening's tasks (Lighthouse's Total Blocking Time). A
 * reader who acts (scrolls, searches with Ctrl+F, presses Tab) gets it at once.
 */
export function openingDone(): Promise<void> {
  return Promise.race([pageSettled(), readerActed()]);
}

/** Whether {@link openingDone} has resolved (the page has settled, or the reader has acted). */
export function isOpeningDone(): boolean {
  return settledNow || actedNow;
}
