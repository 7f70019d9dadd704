/**
 * How much slower than a quiet machine a page runs now, so that a time bound can be scaled to the
 * machine the tests run on (a shared 2-core machine runs them several times slower than a desktop).
 */
import type { Page } from '@playwright/test';

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
