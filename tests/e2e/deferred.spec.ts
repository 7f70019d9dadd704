/**
 * A scene's exam page mounts its first screen first. The bodies of the exam parts and the
 * controls column mount when they come near the screen or in idle time once the page's opening is
 * over (src/ui/Deferred.tsx); formulas are typeset by KaTeX in a worker. In the first tests idle
 * time is switched off (requestIdleCallback never calls back), so only what is near the screen may
 * mount: the test can tell "mounted because near" from "mounted in idle time". The last: a reader
 * who acts before the scene has even mounted ends the opening (the page need not settle first).
 */
import { test, expect } from './fixtures';

test.use({ viewport: { width: 412, height: 823 } });

const pending = '[data-deferred="pending"]';

test.describe('with no idle time', () => {
  test.beforeEach(async ({ page }) => {
    await page.addInitScript(() => {
      (window as unknown as { requestIdleCallback: () => number }).requestIdleCallback = () => 0;
    });
  });

  test('far sections wait; scrolling mounts them; printing mounts everything at once; formulas are typeset in a worker', async ({
    page,
  }) => {
    test.setTimeout(120_000);
    const scripts: string[] = [];
    page.on('request', (r) => {
      let fromPage = false;
      try {
        fromPage = r.frame() === page.mainFrame();
      } catch {
        // a worker's request has no frame
      }
      if (fromPage && r.resourceType() === 'script') scripts.push(r.url());
    });

    await test.step('far sections wait; scrolling mounts them; printing mounts everything at once', async () => {
      await page.goto('./#/texture');
      await page.waitForSelector('main#main');
      // the first screen: the question and its figure
      await expect(page.locator('#question-3-title')).toBeVisible({ timeout: 60_000 });
      await expect(page.locator('.tx-figure svg').first()).toBeVisible({ timeout: 60_000 });
      // far below: still placeholders (each keeps an estimated height)
      await expect(page.locator(pending).first()).toBeAttached();
      const far = await page.locator(pending).count();
      expect(far).toBeGreaterThan(0);
      expect(
        await page
          .locator(pending)
          .first()
          .evaluate((el) => el.getBoundingClientRect().height),
      ).toBeGreaterThan(100);
      // scrolling to a part mounts it
      await page.locator('#part-3c').scrollIntoViewIfNeeded();
      await expect(page.getByTestId('answer-3c')).toHaveCount(1, { timeout: 30_000 });
      // before printing, everything mounts synchronously (within the beforeprint event)
      const left = await page.evaluate((sel) => {
        window.dispatchEvent(new Event('beforeprint'));
        return document.querySelectorAll(sel).length;
      }, pending);
      expect(left).toBe(0);
      // what is beyond the exam is folded: its folds are there, closed, their content not mounted
      await expect(
        page.getByTestId('explore-further').locator('details[data-fold]:not([open])').first(),
      ).toBeAttached();
    });

    await test.step('formulas are typeset (in a worker) and the page never loads KaTeX itself', async () => {
      await page.goto('./#/hemisphere');
      // the question's statement on the first screen is typeset
      await expect(page.locator('#question-1 .katex').first()).toBeAttached({ timeout: 60_000 });
      const html = await page.locator('#question-1 .katex').first().innerHTML();
      expect(html).toContain('katex-mathml'); // HTML + MathML for screen readers
      expect(
        scripts.filter((u) => /vendor-katex/.test(u)),
        'KaTeX is not loaded on the main thread',
      ).toEqual([]);
    });
  });

  test("printing also mounts the sections nested in the sections it mounts (the ray-sphere exam part's blocks)", async ({
    page,
  }) => {
    // an observer that never reports: no section comes near the screen, so only printing mounts them
    await page.addInitScript(() => {
      (window as unknown as { IntersectionObserver: unknown }).IntersectionObserver = class {
        observe() {}
        unobserve() {}
        disconnect() {}
        takeRecords() {
          return [];
        }
      };
    });
    // the precision table is in a fold: open, printing mounts it too
    await page.goto('./#/ray-sphere?open=precision');
    await expect(page.locator('#question-5-title')).toBeVisible({ timeout: 60_000 });
    await expect(page.locator(pending).first()).toBeAttached();
    await expect(page.getByTestId('cross-section')).toHaveCount(0);
    const { left, labels } = await page.evaluate((sel) => {
      window.dispatchEvent(new Event('beforeprint'));
      return {
        left: document.querySelectorAll(sel).length,
        // read in the same task: no frame has been painted since the print began
        labels: document.querySelector('[data-testid="cross-section"]')?.getAttribute('data-labels'),
      };
    }, pending);
    expect(left).toBe(0);
    // the cross-section mounted for the print has its labels placed already
    expect(labels).toBe('placed');
    for (const id of ['cross-section', 'g-plot', 'derivation', 'live-answer', 'precision-table'])
      await expect(page.getByTestId(id)).toHaveCount(1);
  });
});

test('a reader who acts as the page loads, before its scene has mounted, gets the far sections before the page settles', async ({
  page,
}) => {
  // (the fixtures' reader acts as the document is parsed: ./fixtures.ts readerActs) Recorded from
  // the first script on: whether sections were pending, and whether the page had settled when
  // the last of them mounted.
  await page.addInitScript(() => {
    const rec = { sawPending: false, settledWhenAllMounted: null as boolean | null };
    (window as unknown as { __mounts: typeof rec }).__mounts = rec;
    new MutationObserver(() => {
      if (document.querySelector('[data-deferred="pending"]')) rec.sawPending = true;
      else if (rec.sawPending && rec.settledWhenAllMounted === null)
        rec.settledWhenAllMounted = document.documentElement.hasAttribute('data-settled');
    }).observe(document, { subtree: true, childList: true, attributes: true });
  });
  await page.goto('./#/hemisphere');
  await page.waitForSelector('main#main');
  await expect(page.locator(pending)).toHaveCount(0, { timeout: 30_000 });
  const rec = await page.evaluate(
    () =>
      (window as unknown as { __mounts: { sawPending: boolean; settledWhenAllMounted: boolean } }).__mounts,
  );
  expect(rec).toEqual({ sawPending: true, settledWhenAllMounted: false });
});
