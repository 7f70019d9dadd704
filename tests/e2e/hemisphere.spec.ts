/**
 * Browser tests of #/hemisphere (exam Q1, Q2). Expected values come from closed forms
 * (k = 2/(e^{2π} − 1), ∫ cos θ dω = π, …) and from the scene's own pure model run here in Node
 * (same core code, same seed and point set), so "the readout equals the core's value" is checked
 * directly. Nothing is copied from the answer key.
 */
import type { Page } from '@playwright/test';
import { test, expect, openScene, readout, readoutNumber, waitForReadout } from './fixtures';
import { computeDrawStats } from '../../src/scenes/hemisphere/drawStats';
import { lobeFromParams } from '../../src/scenes/hemisphere/lobe';
import { examLobeK } from '../../src/core/sampling';
import type { LobeId } from '../../src/scenes/hemisphere/params';

const cosTheta = (t: number) => Math.cos(t);
const rel = (a: number, b: number) => Math.abs(a - b) / Math.max(1e-300, Math.abs(b));

/** Open a scene without waiting for its deferred sections (the page is still loading). */
async function openSceneNoWait(page: Page, hash: string) {
  await page.goto(`./${hash}`);
  await page.waitForSelector('[data-testid="stats-status"]');
}

/** Wait until the worker's statistics for the current parameters are on screen. */
async function statsReady(page: Page) {
  await expect(page.getByTestId('stats-status')).toHaveAttribute('data-state', 'ready', { timeout: 30_000 });
}

async function expectMatchesCore(
  page: Page,
  lobeId: LobeId,
  n: number,
  seed: number,
  exponent = 8,
  custom?: (t: number, p: number) => number,
) {
  const built = lobeFromParams(lobeId, exponent, custom);
  if (built.tab && !built.tab.ok) throw new Error(built.tab.message);
  const lobe = built.lobe!;
  const core = computeDrawStats(lobe, cosTheta, 'independent', seed, n);
  expect(Number(await readout(page, lobeId === 'exam' ? 'k' : 'k-chosen'))).toBe(lobe.k);
  // a link followed on the open page: the previous draw's "ready" may be seen before the new run
  // starts, so wait for this draw's count (each call here has its own n), then for its statistics
  await waitForReadout(page, 'samples', (v) => Number(v) === n);
  await statsReady(page);
  expect(rel(await readoutNumber(page, 'chi2-p'), core.chi2!.pValue)).toBeLessThan(1e-9);
  expect(rel(await readoutNumber(page, 'mc-exact'), core.exact)).toBeLessThan(1e-12);
  expect(rel(await readoutNumber(page, 'mc-uniform'), core.q2.uniform.estimate)).toBeLessThan(1e-12);
  expect(rel(await readoutNumber(page, 'mc-importance'), core.q2.importance.estimate)).toBeLessThan(1e-12);
  return core;
}

test.describe('Q1: the exam lobe', () => {
  test('wiring: k, χ² and the estimates on the page equal the core for the exam, Phong and a typed lobe', async ({
    page,
  }) => {
    await openScene(page, '#/hemisphere');
    await statsReady(page);
    // the exam's answer (a): k = 2/(e^{2π} − 1)
    expect(Number(await readout(page, 'k'))).toBe(examLobeK());
    const core = await expectMatchesCore(page, 'exam', 20000, 1);
    expect(core.chi2!.pass).toBe(true);
    await expect(page.getByTestId('chi2-verdict')).toContainText('Accepted');
    await expect(page.getByTestId('derivation')).toContainText('Normalize');

    await openScene(page, '#/hemisphere?lobe=phong&n=5000&seed=7');
    await statsReady(page);
    await expectMatchesCore(page, 'phong', 5000, 7);

    // the typed density's own derivation is folded under Explore further: the link opens it
    await openScene(page, '#/hemisphere?lobe=custom&pdf=cos(theta)&n=4000&seed=3&open=lobe-derivation');
    await statsReady(page);
    await expectMatchesCore(page, 'custom', 4000, 3, 8, (t) => Math.cos(t));
    await expect(page.getByTestId('derivation')).toContainText('Numerical steps');
  });

  test('"More settings" is folded and remembered in the link; changing the lobe there updates the URL and the readouts', async ({
    page,
  }) => {
    await openScene(page, '#/hemisphere?n=2000');
    // closed on load, nothing mounted inside; opened by a click, which writes open=settings
    const fold = page.getByTestId('fold-settings');
    await expect(fold).not.toHaveAttribute('open');
    await expect(page.getByTestId('lobe')).toHaveCount(0);
    await fold.locator('summary').click();
    await expect(page).toHaveURL(/[?&]open=settings(&|$)/);
    await expect(page.getByTestId('lobe')).toBeVisible();
    // the link keeps it open
    await page.reload();
    await expect(page.getByTestId('fold-settings')).toHaveAttribute('open');
    await statsReady(page);
    await page.getByTestId('lobe').selectOption('uniform');
    await expect(page).toHaveURL(/lobe=uniform/);
    // the chosen density's k is in the note naming it; Q1(a)'s answer keeps the exam's k
    await waitForReadout(page, 'k-chosen', (v) => Number(v) === 1 / (2 * Math.PI));
    expect(Number(await readout(page, 'k'))).toBe(examLobeK());
    await statsReady(page);
    await expectMatchesCore(page, 'uniform', 2000, 1);
  });
});

test.describe("the key's inverted Jacobian", () => {
  test('jacobian=inverted: a clear message, the divergence, and no garbage numbers', async ({ page }) => {
    await openScene(page, '#/hemisphere?jacobian=inverted');
    await expect(page.getByTestId('inverted-message')).toContainText('Not integrable');
    await statsReady(page);
    expect(await readout(page, 'samples')).toBe('none');
    expect(await readout(page, 'chi2-p')).toBe('none');
    expect(await readout(page, 'mc-importance')).toBe('none');
    // part (a) is unaffected, and so is the uniform estimator
    expect(Number(await readout(page, 'k'))).toBe(examLobeK());
    expect(rel(await readoutNumber(page, 'mc-exact'), Math.PI)).toBeLessThan(1e-12);
    // the partial integral −ln sin ε at the default ε = 1e-3
    const partial = await readoutNumber(page, 'inverted-partial');
    expect(rel(partial, -Math.log(Math.sin(1e-3)))).toBeLessThan(1e-12);
    await expect(page.locator('main')).not.toContainText('NaN');
    await expect(page.locator('main')).not.toContainText('Infinity');
  });
});

test.describe('typed densities', () => {
  test('typing a density in the field samples it', async ({ page }) => {
    await openScene(page, '#/hemisphere?lobe=custom&n=3000&open=settings');
    await statsReady(page);
    const input = page.getByTestId('pdf-input');
    await input.fill('1');
    await input.press('Enter');
    await expect(page).toHaveURL(/pdf=1/);
    await waitForReadout(page, 'k-chosen', (v) => Math.abs(Number(v) * 2 * Math.PI - 1) < 1e-9);
    await statsReady(page);
    expect(Number(await readout(page, 'samples'))).toBe(3000);
  });

  test('typed densities that are negative, not integrable, not finite, not parsed: a clear message each, nothing breaks; a bad f too', async ({
    page,
  }) => {
    const bad = [
      ['cos(theta) - 0.5', /negative/],
      ['cos(theta)/sin(theta)^2', /not integrable/],
      ['1/cos(theta)', /not integrable/],
      ['sqrt(1 - 2*theta)', /not a finite number/],
      ['cos(theta', /syntax|parenthesis|expected/i],
      ['cos(x)', /unknown|x/],
    ] as const;
    const input = page.getByTestId('pdf-input');
    for (const [i, [pdf, message]] of bad.entries()) {
      // the first from the link, the others typed
      if (i === 0)
        await openScene(page, `#/hemisphere?lobe=custom&n=2000&open=settings&pdf=${encodeURIComponent(pdf)}`);
      else {
        await input.fill(pdf);
        await input.press('Enter');
      }
      await expect(page.getByTestId('custom-error'), pdf).toContainText(message);
      await statsReady(page);
      // no chosen density, so no k of its own; Q1(a)'s answer is still the exam's
      await expect(page.getByTestId('k-chosen')).toHaveCount(0);
      expect(Number(await readout(page, 'k'))).toBe(examLobeK());
      expect(await readout(page, 'samples'), pdf).toBe('none');
      expect(await readout(page, 'chi2-p'), pdf).toBe('none');
      expect(await readout(page, 'mc-importance'), pdf).toBe('none');
      // Q2's exact value and the uniform estimate still work
      expect(rel(await readoutNumber(page, 'mc-exact'), Math.PI)).toBeLessThan(1e-12);
      await expect(page.locator('main')).not.toContainText('NaN');
    }
    // and fixing it recovers
    await input.fill('cos(theta)');
    await input.press('Enter');
    await expect(page.getByTestId('custom-error')).toHaveCount(0);
    await waitForReadout(page, 'k-chosen', (v) => Math.abs(Number(v) * Math.PI - 1) < 1e-3);

    // a bad integrand f: its message, the estimates off, the rest works
    await openScene(page, '#/hemisphere?n=2000&f=' + encodeURIComponent('cos(theta'));
    await statsReady(page);
    await expect(page.locator('.expr-field [role=alert]').first()).toBeVisible();
    expect(await readout(page, 'mc-uniform')).toBe('none');
    expect(await readout(page, 'mc-importance')).toBe('none');
    expect(Number(await readout(page, 'k'))).toBe(examLobeK());
  });
});

test.describe('robustness and extras', () => {
  test('the opening statistics wait for the page to load; a change before then runs at once', async ({
    page,
  }) => {
    // every state the status line shows, and when the statistics task goes to a worker, from the
    // start (the 3D view's points stream from a worker of their own at once: not logged)
    await page.addInitScript(() => {
      const w = window as unknown as { __log: string[] };
      w.__log = [];
      const Orig = window.Worker;
      window.Worker = class extends Orig {
        override postMessage(msg: unknown, transfer?: Transferable[] | StructuredSerializeOptions) {
          if ((msg as { method?: string } | null)?.method === 'stats')
            w.__log.push(document.documentElement.hasAttribute('data-settled') ? 'worker settled' : 'worker');
          super.postMessage(msg, transfer as Transferable[]);
        }
      };
      new MutationObserver(() => {
        const s = document.querySelector('[data-testid="stats-status"]')?.getAttribute('data-state');
        const settled = document.documentElement.hasAttribute('data-settled') ? ' settled' : '';
        if (s && w.__log.at(-1) !== s + settled) w.__log.push(s + settled);
      }).observe(document, {
        subtree: true,
        childList: true,
        attributes: true,
        attributeFilter: ['data-state'],
      });
    });
    await openScene(page, '#/hemisphere?n=500');
    await statsReady(page);
    const log = await page.evaluate(() => (window as unknown as { __log: string[] }).__log);
    // first waiting (no worker yet), then, once the page has settled, the run and its result
    expect(log[0]).toBe('waiting');
    const w = log.findIndex((s) => s.startsWith('worker'));
    expect(log[w]).toBe('worker settled');
    expect(log.slice(0, w).filter((s) => s.startsWith('running'))).toEqual([]);
    expect(log.slice(w)).toContain('ready settled');
    await expect(page.getByTestId('stats-status')).toHaveText('statistics up to date');

    // a change while the page is still loading is not held back
    await page.goto('about:blank');
    await openSceneNoWait(page, '#/hemisphere?n=400');
    await expect(page.getByTestId('stats-status')).toHaveAttribute('data-state', 'waiting');
    await page.evaluate(() => (location.hash = '#/hemisphere?n=300'));
    await statsReady(page);
    expect(Number(await readout(page, 'samples'))).toBe(300);
    const log2 = await page.evaluate(() => (window as unknown as { __log: string[] }).__log);
    expect(log2.find((s) => s.startsWith('running'))).toBe('running'); // before the page settled
  });

  test('10⁶ points: the growth reaches a million points in the 3D view', async ({ page }) => {
    test.setTimeout(150_000);
    await openScene(page, '#/hemisphere?n=1000000');
    const view = page.getByTestId('hemisphere-3d');
    await view.scrollIntoViewIfNeeded();
    await expect(view).toHaveAttribute('data-status', 'ready', { timeout: 30_000 });
    await expect(page.getByTestId('shown-count')).toHaveAttribute('data-value', '1000000', {
      timeout: 90_000,
    });
    // the points came from the worker in chunks that add up to the million
    const grown = await page.evaluate(() =>
      performance
        .getEntriesByName('hemisphere-grow')
        .reduce((a, e) => a + ((e as PerformanceMeasure).detail as number), 0),
    );
    expect(grown).toBeGreaterThanOrEqual(1_000_000);
    await expect(view).toHaveAttribute('data-status', 'ready');
  });
});
