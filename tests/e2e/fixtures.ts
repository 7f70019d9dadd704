/**
 * Shared browser-test fixtures: every test fails on any console error or uncaught page error;
 * helpers open a scene and read readouts the way the contract defines them.
 */
import { test as base, expect, type Frame, type Page } from '@playwright/test';

export const test = base.extend<{
  consoleErrors: string[];
  backOnline: void;
  readerActs: void;
  framesOnFailure: void;
}>({
  // Every page a test opens has a reader who acts at once: a wheel event that scrolls nothing, as
  // the document is parsed. The work far below a page's first screen (sections mounted late,
  // formulas typeset: src/ui/Deferred.tsx, src/ui/mathQueue.ts) waits for the page's opening to
  // be over, which is when the page has settled (0.5–3 s) or when its reader acts
  // (src/ui/whenQuiet.ts openingDone); a test reads that work at once, as a reader who scrolls
  // would. A page recorded for its first screen (./firstScreen.ts) is one whose reader only looks.
  readerActs: [
    async ({ context }, use) => {
      await context.addInitScript(() =>
        document.addEventListener('DOMContentLoaded', () => {
          if (!('__firstScreen' in window)) window.dispatchEvent(new WheelEvent('wheel'));
        }),
      );
      await use();
    },
    { auto: true },
  ],
  // One browser context serves a worker's tests one after another (playwright.config.ts,
  // reuseContext): between tests Playwright takes it back to about:blank and resets its storage,
  // routes, init scripts, viewport and media, but not the offline switch a test may have thrown.
  backOnline: [
    async ({ context }, use) => {
      await use();
      await context.setOffline(false);
    },
    { auto: true },
  ],
  // A failed test's page, described for its report: whether it still draws animation frames and
  // what its canvases are. Headless Chromium has been seen to stop drawing frames on a page with a
  // live WebGL canvas, which makes every wait that needs a frame time out (a media query's change,
  // Playwright's "element is stable"); this says which page state a failure came from.
  framesOnFailure: [
    async ({ page }, use, testInfo) => {
      await use();
      if (testInfo.status === testInfo.expectedStatus || page.isClosed()) return;
      const canvases = await Promise.race([
        page.evaluate(() =>
          [...document.querySelectorAll('canvas')].map((c) => {
            const r = c.getBoundingClientRect();
            // a WebGL canvas returns its context here, a 2D one null (one with none yet gets one)
            const gl = c.getContext('webgl2') ?? c.getContext('webgl');
            return `${c.width}×${c.height}${r.bottom < 0 || r.top > innerHeight ? ' off screen' : ''}${gl ? ` webgl${gl.isContextLost() ? ' LOST' : ''}` : ''}`;
          }),
        ),
        new Promise<string>((resolve) => setTimeout(() => resolve('no answer in 5 s'), 5000)),
      ]).catch((e: unknown) => String(e).slice(0, 160));
      const state = { url: page.url(), ...(await frameState(page, 3000)), canvases };
      await testInfo.attach('page state at the failure', {
        body: JSON.stringify(state, null, 1),
        contentType: 'text/plain',
      });
    },
    { auto: true },
  ],
  consoleErrors: [
    async ({ page }, use) => {
      const errors: string[] = [];
      page.on('console', (m) => {
        if (m.type() === 'error') errors.push(`console.error: ${m.text()}`);
      });
      page.on('pageerror', (e) => errors.push(`pageerror: ${e.message}`));
      await use(errors);
      expect(errors, 'console errors during the test').toEqual([]);
    },
    { auto: true },
  ],
});

export { expect };

/**
 * Navigate to a hash route (e.g. '#/texture?u=0.4') and wait until the scene has loaded, every
 * section of its page mounted (the page's reader has acted: see `readerActs` above).
 */
export async function openScene(page: Page, hash: string): Promise<void> {
  await page.goto(`./${hash.startsWith('#') ? hash : `#${hash}`}`);
  await page.waitForSelector('main#main');
  await expect(page.locator('.loading')).toHaveCount(0);
  await expect(page.locator('[data-deferred="pending"]')).toHaveCount(0, { timeout: 30_000 });
}

/**
 * Follows a link (by default the page's own) anew: leaves for the home page, then goes to the link,
 * so the route mounts from the link alone (nothing kept in memory) without reloading the app. What
 * a link pasted into the same tab does; a reload also re-reads storage, which this does not test.
 */
export async function followLinkAnew(page: Page, link = new URL(page.url()).hash): Promise<void> {
  await page.evaluate(() => (location.hash = '#/'));
  await expect(page.locator('main#main.home')).toBeVisible();
  await page.evaluate((h) => (location.hash = h), link);
  await expect(page.locator('main#main.home')).toHaveCount(0);
}

/**
 * Give a practice answer: type it into its field, or, where the answer is a choice (a select),
 * choose the option it names.
 */
export async function giveAnswer(root: Page | Frame, name: string, text: string): Promise<void> {
  const el = root.getByTestId(`answer-${name}`);
  if ((await el.evaluate((e) => e.tagName)) === 'SELECT') await el.selectOption(text);
  else await el.fill(text);
}

/** The `data-value` of a readout (the contract's full-precision value, or "none"). */
export async function readout(page: Page, id: string): Promise<string> {
  const loc = page.getByTestId(id).first();
  await expect(loc).toHaveAttribute('data-value', /.*/);
  return (await loc.getAttribute('data-value')) ?? '';
}

/** A readout as a number (fails the test if it is "none" or not numeric). */
export async function readoutNumber(page: Page, id: string): Promise<number> {
  const v = await readout(page, id);
  const x = Number(v);
  expect(Number.isFinite(x), `readout ${id} = ${v} is a finite number`).toBe(true);
  return x;
}

/** Wait until a readout's data-value satisfies a predicate (scenes compute asynchronously). */
export async function waitForReadout(
  page: Page,
  id: string,
  pred: (v: string) => boolean,
  timeout = 15000,
): Promise<string> {
  let last = '';
  await expect
    .poll(
      async () => {
        last = (await page.getByTestId(id).first().getAttribute('data-value')) ?? '';
        return pred(last);
      },
      { timeout },
    )
    .toBe(true);
  return last;
}

/**
 * Count requestAnimationFrame calls from the page's first script on, in `window.__raf`, and the
 * requests not yet run or cancelled, in `window.__rafPending` (call before the page loads). A render
 * loop always has a frame requested, so "nothing renders while paused / idle" is `__rafPending`
 * at 0 (a state, no clock needed), and `__raf` says how many frames a change cost.
 */
export async function countAnimationFrames(page: Page): Promise<void> {
  await page.addInitScript(() => {
    const w = window as unknown as { __raf: number; __rafPending: number };
    w.__raf = 0;
    w.__rafPending = 0;
    const pending = new Set<number>();
    const request = window.requestAnimationFrame.bind(window);
    const cancel = window.cancelAnimationFrame.bind(window);
    window.requestAnimationFrame = (cb) => {
      w.__raf++;
      const id = request((t) => {
        pending.delete(id);
        w.__rafPending = pending.size;
        cb(t);
      });
      pending.add(id);
      w.__rafPending = pending.size;
      return id;
    };
    window.cancelAnimationFrame = (id) => {
      pending.delete(id);
      w.__rafPending = pending.size;
      cancel(id);
    };
  });
}

/**
 * Resolves once the main thread has rendered two frames and run a macrotask (it is free again).
 * A compositor that skips frames (seen on a loaded machine: no animation frame for minutes while
 * scrolling) must not hang the test, so a 2 s timer also resolves it: a timer still needs a free
 * main thread, so a page that blocks its main thread still keeps the test waiting.
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

/**
 * What a page says of its frames, for a failure message: its visibility, and whether an animation
 * frame ran within `ms` (headless Chromium has been seen drawing none for minutes on a loaded
 * machine; observers, media-query changes and Playwright's "holds still" checks all wait for frames).
 */
export async function frameState(
  page: Page,
  ms = 1000,
): Promise<{ frame: boolean; visibility: string } | { error: string }> {
  return page
    .evaluate(
      (ms) =>
        new Promise<{ frame: boolean; visibility: string }>((resolve) => {
          let frame = false;
          requestAnimationFrame(() => (frame = true));
          setTimeout(() => resolve({ frame, visibility: document.visibilityState }), ms);
        }),
      ms,
    )
    .catch((e: unknown) => ({ error: `no answer from the page (${String(e)})` }));
}
