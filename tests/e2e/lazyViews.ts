import type { Page } from '@playwright/test';

const LOADING = /Loading plot…|Loading 3D view…|Loading the scene…/;

/**
 * Bring every lazy view of the page (plots, 3D views) on screen, one after another, and wait until
 * each has finished loading its chunk (views load only while on screen, so a quick scroll past is
 * not enough on a busy machine).
 */
export async function settleLazyViews(page: Page, timeout = 60000): Promise<void> {
  const h = await page.evaluate(() => document.documentElement.scrollHeight);
  for (let y = 0; y < h; y += 600) await page.evaluate((y) => window.scrollTo(0, y), y);
  for (let i = 0; i < 50; i++) {
    const el = await page
      .getByText(LOADING)
      .first()
      .elementHandle({ timeout: 1000 })
      .catch(() => null);
    if (!el) return;
    await el.scrollIntoViewIfNeeded().catch(() => undefined);
    // polled on a timer, not per animation frame: a page that draws no frames for a while (a
    // loaded machine, nothing changing on screen) must not stall the wait
    await page.waitForFunction((e) => !e.isConnected || !/Loading/.test(e.textContent ?? ''), el, {
      timeout,
      polling: 200,
    });
  }
  throw new Error('views still loading after 50 rounds');
}
