/**
 * Long main-thread tasks in browser tests: a PerformanceObserver for 'longtask' in the page, and
 * how much slower than a quiet machine the page runs now, so that a bound can be scaled to the
 * machine the tests run on (a shared 2-core machine runs them several times slower than a desktop).
 */
import type { Page } from '@playwright/test';

/** Start collecting the durations of the page's long tasks (over 50 ms, the API's threshold). */
export async function installLongTaskObserver(page: Page): Promise<void> {
  await page.evaluate(() => {
    const w = window as unknown as { __long: number[] };
    w.__long = [];
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) w.__long.push(e.duration);
    }).observe({ type: 'longtask', buffered: false });
  });
}

/** The long tasks' durations since the observer started or since the last call (ms). */
export async function takeLongTasks(page: Page): Promise<number[]> {
  return page.evaluate(() => {
    const w = window as unknown as { __long: number[] };
    const l = w.__long.slice();
    w.__long.length = 0;
    return l;
  });
}

/**
 * How much slower than a quiet machine this page's main thread runs now (≥ 1): a fixed loop that
 * takes ~10 ms on a quiet desktop core, timed three times, the fastest kept. A long-task bound is
 * scaled by it, so a machine shared by many test runs does not fail a test, while an input that
 * costs far more work than it should still does.
 */
export async function slowdown(page: Page): Promise<number> {
  const ms = await page.evaluate(() => {
    let best = Infinity;
    for (let r = 0; r < 3; r++) {
      const t0 = performance.now();
      let acc = 0;
      for (let i = 0; i < 10_000_000; i++) acc += Math.sqrt(i);
      const t = performance.now() - t0;
      if (acc > 0) best = Math.min(best, t);
    }
    return best;
  });
  return Math.max(1, ms / 10);
}

/**
 * Resolves once the main thread has rendered two frames and run a macrotask (it is free again).
 * A compositor that skips frames (seen once on a loaded machine: no animation frame for minutes
 * while scrolling the default page) must not hang the test, so a 2 s timer also resolves it: a
 * timer still needs a free main thread, so a page that blocks its main thread still fails (and
 * long tasks are measured separately).
 */
export async function settle(page: Page): Promise<void> {
  await page.evaluate(
    () =>
      new Promise<void>((resolve) => {
        const timer = setTimeout(resolve, 2000);
        requestAnimationFrame(() =>
          requestAnimationFrame(() =>
            setTimeout(() => {
              clearTimeout(timer);
              resolve();
            }, 0),
          ),
        );
      }),
  );
}
