/**
 * The single-file copy (`npm run build:single` → dist-single/index.html) opens from file:// with no
 * server and no network: the home page, every scene with its workers, and the worksheet (practice
 * questions with their QR codes) work.
 */
import { existsSync } from 'node:fs';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { test, expect } from './fixtures';
import { settleLazyViews } from './lazyViews';
import { cspViolations, injectScript, INJECTION_REFUSED, recordCspViolations } from './csp';
import { SCENES, type SceneId } from '../../src/kit/catalogue';

const file = resolve(process.env.E2E_SINGLE ?? 'dist-single/index.html');

// A readout each scene computes (the catalogue's key readout), and where a scene has one, a readout
// that comes from a worker (monte-carlo's `estimate`, hemisphere's `mc-uniform`), to prove the
// inlined workers run from file://.
const WORKER_READOUT: Partial<Record<SceneId, string>> = {
  hemisphere: 'mc-uniform',
  'monte-carlo': 'estimate',
  'area-light': 'estimate',
};
const ROUTES: [string, string[]][] = [
  ['#/', []],
  ...SCENES.map((s): [string, string[]] => [
    // the plots of monte-carlo's Explore further are folded: its link opens one, so that a plot draws
    s.id === 'monte-carlo' ? `#${s.path}?open=convergence` : `#${s.path}`,
    [s.keyReadout, ...(WORKER_READOUT[s.id] ? [WORKER_READOUT[s.id]!] : [])],
  ]),
  ['#/practice/sheet?seed=1&q=1,3,5', []],
];
/**
 * Routes whose lazy views (plots, the 3D view, formulas typeset in a worker) are all brought on
 * screen: one with plots and workers, one with three.js (texture's sphere, the lightest scene with a
 * 3D view). The lazy parts are inlined in the one file in the same way for every route, so two
 * prove the mechanism.
 */
const WHOLE = new Set(['#/monte-carlo?open=convergence', '#/texture']);

test('the single HTML file opens from file:// and its routes work with no network, under its CSP', async ({
  page,
  context,
  consoleErrors,
}) => {
  test.setTimeout(240_000);
  expect(existsSync(file), `${file} exists (run "npm run build:single")`).toBe(true);
  await recordCspViolations(context);
  // nothing may leave the file: any http(s) request fails the test
  const requests: string[] = [];
  await context.route(/^https?:/, (route) => {
    requests.push(route.request().url());
    return route.abort();
  });
  await context.setOffline(true);
  const url = pathToFileURL(file).href;
  for (const [i, [hash, ids]] of ROUTES.entries()) {
    // the file is loaded once; each further route is a link followed on the open page (the one
    // file holds every route, and reading its 7 MB again per route would only repeat the first load)
    if (i === 0) await page.goto(`${url}${hash}`);
    else await page.evaluate((h) => (location.hash = h), hash);
    await expect(page).toHaveURL(`${url}${hash}`);
    await expect(page.locator('main#main:visible')).toBeVisible({ timeout: 30000 });
    await expect(page.locator('.loading')).toHaveCount(0, { timeout: 30000 });
    for (const id of ids)
      await expect(page.getByTestId(id).first()).toHaveAttribute('data-value', /^-?\d/, { timeout: 60000 });
    // the worksheet: its questions' QR codes drawn
    if (hash.startsWith('#/practice/sheet')) {
      await expect(page.getByTestId('sheet-qr').first()).toBeVisible({ timeout: 30000 });
      await expect(page.getByTestId('sheet-qr-pending')).toHaveCount(0, { timeout: 30000 });
    }
    // bring every lazy view (plots, 3D, formulas) on screen so their chunks load
    if (WHOLE.has(hash)) await settleLazyViews(page);
    // three.js came from the file: the texture's sphere view is drawn
    if (hash === '#/texture') {
      const view = page.getByTestId('sphere-view');
      await view.scrollIntoViewIfNeeded();
      await expect(view).toHaveAttribute('data-status', 'ready', { timeout: 60000 });
    }
    await expect(page.locator('.notice-error')).toHaveCount(0);
    // the file's inline app runs by its hash, its workers from Blob URLs: nothing is refused
    expect(await cspViolations(page), `CSP violations on ${hash}`).toEqual([]);
  }
  // an inline script or handler injected into the file's page does not run
  const injected = await injectScript(page);
  expect(injected.ran).toEqual([]);
  expect(injected.reported).toEqual(['script-src-elem inline', 'script-src-attr inline']);
  expect(consoleErrors.filter((e) => INJECTION_REFUSED.test(e))).toHaveLength(2);
  consoleErrors.splice(0, consoleErrors.length, ...consoleErrors.filter((e) => !INJECTION_REFUSED.test(e)));
  await page.goto(`${url}#/texture?u=0.7`);
  await page.getByTestId('copy-link').click();
  // a link copied from the file is the file's own URL
  await expect(page.getByTestId('share-text')).toHaveValue(
    new RegExp(`^${url.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}#/texture\\?u=0\\.7`),
  );
  expect(requests).toEqual([]);
});
