import type { Page } from '@playwright/test';
import { frameState } from './fixtures';

const LOADING = /Loading plot…|Loading 3D view…|Loading the scene…/;
/** What a plot says in place of its chart when the chart could not be loaded or laid out (src/ui/Plot.tsx). */
const FAILED = /The plot could not be drawn/;

/**
 * Bring every lazy view of the page (plots, 3D views) on screen, one after another, and wait until
 * each has finished loading its chunk (views load only while on screen, so a quick scroll past is
 * not enough on a busy machine). The page is brought to the front first: a tab behind another one
 * may draw no frames, and a view loads only in a frame. Every wait has a limit, and a view that
 * does not load is named in the error, with what the page says of its frames.
 */
export async function settleLazyViews(page: Page, timeout = 60000): Promise<void> {
  await page.bringToFront();
  const h = await page.evaluate(() => document.documentElement.scrollHeight);
  for (let y = 0; y < h; y += 600) await page.evaluate((y) => window.scrollTo(0, y), y);
  for (let i = 0; i < 50; i++) {
    // (a view shows its placeholder from its first render until its chunk has drawn it: none
    // left means every view is in)
    const loading = page.getByText(LOADING).first();
    if ((await loading.count()) === 0) {
      // loaded is not enough: every plot is drawn (its chart's chunk came, its data laid out)
      const failed = await page.getByText(FAILED).allTextContents();
      if (failed.length) throw new Error(`${failed.length} view(s) failed: ${failed.join('; ')}`);
      return;
    }
    const el = await loading.elementHandle({ timeout: 1000 }).catch(() => null);
    if (!el) continue;
    // (scrolling waits for the element to hold still over two frames: limited, as the wait below)
    await el.scrollIntoViewIfNeeded({ timeout }).catch(() => undefined);
    // polled on a timer, not per animation frame: a page that draws no frames for a while (a
    // loaded machine, nothing changing on screen) must not stall the wait
    const done = await page
      .waitForFunction((e) => !e.isConnected || !/Loading/.test(e.textContent ?? ''), el, {
        timeout,
        polling: 200,
      })
      .then(
        () => true,
        () => false,
      );
    if (!done) {
      const what = await el
        .evaluate((e) => `"${e.textContent}" in ${e.parentElement?.outerHTML.slice(0, 200) ?? 'nothing'}`)
        .catch(() => 'a view');
      throw new Error(
        `still loading after ${timeout} ms: ${what}; the page: ${JSON.stringify(await frameState(page))}`,
      );
    }
  }
  throw new Error('views still loading after 50 rounds');
}
