/**
 * Offline: after one visit to any page, the service worker has precached the whole build (every
 * file the app loads is in its cache), so with the host gone a scene never opened before loads and
 * works, with zero console errors. A new build is picked up with the "updated, reload" notice,
 * never a mix of chunks, and no tab is reloaded but by its reader. One test walks through both, on
 * the same two tabs, because the worker's install (the whole build, stored) is its costly part.
 *
 * It serves its own copy of the build on an ephemeral port, so it can take the host down and
 * "deploy" a new build without touching the shared one.
 */
import { cpSync, readFileSync, rmSync, writeFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from '@playwright/test';
import { test, expect } from './fixtures';
import { serveBuildCopy } from './buildCopy';
import { settleLazyViews } from './lazyViews';
import { cspViolations, injectScript, INJECTION_REFUSED, recordCspViolations } from './csp';
import { withCsp } from '../../scripts/csp';
import { SCENES as CATALOGUE } from '../../src/kit/catalogue';

const dist = process.env.E2E_DIST ?? 'dist';

// this file's tests need the service worker that the other specs block (playwright.config.ts)
test.use({ serviceWorkers: 'allow' });

/** Wait until the service worker controls the page (it activates only after precaching everything). */
async function waitForServiceWorker(page: Page): Promise<void> {
  await page.evaluate(() => navigator.serviceWorker.ready.then(() => undefined));
  await expect
    .poll(() => page.evaluate(() => navigator.serviceWorker.controller !== null), { timeout: 60000 })
    .toBe(true);
}

/** The build's files that a page may load: scripts, styles, the fonts it uses, and the app's shell. */
function appFiles(): string[] {
  const files = JSON.parse(readFileSync(join(dist, 'app-files.json'), 'utf8')) as string[];
  // KaTeX ships each font three ways; browsers that run the app take the woff2
  return files.filter((f) => !/\.(woff|ttf)$/.test(f));
}

const key = (id: string) => CATALOGUE.find((s) => s.id === id)!;

/**
 * "Deploy" a real rebuild into the served folder: every file under assets/ gets a new name (as a
 * build with changed sources does), every reference to it in the build's text files follows, the
 * old files are gone from the host, and index.html carries a marker (with its new revision in the
 * service worker's precache list) and its Content-Security-Policy for its new inline script.
 * Returns the marker.
 */
function deployRenamedBuild(dir: string): string {
  const marker = `rebuilt-${Date.now()}`;
  const assets = readdirSync(join(dir, 'assets'));
  const renames = assets.map((name) => [name, name.replace(/(\.[a-z0-9]+)$/i, 'v2$1')] as const);
  // longest first, and only whole names, so one name inside another is never half-renamed
  renames.sort((a, b) => b[0].length - a[0].length);
  const rename = (text: string) => {
    let out = text;
    for (const [from, to] of renames) out = out.split(from).join(to);
    return out;
  };
  for (const [from, to] of renames) {
    const path = join(dir, 'assets', from);
    if (/\.(js|css|html|json|webmanifest)$/.test(from))
      writeFileSync(join(dir, 'assets', to), rename(readFileSync(path, 'utf8')));
    else cpSync(path, join(dir, 'assets', to));
    rmSync(path);
  }
  const html = rename(readFileSync(join(dir, 'index.html'), 'utf8')).replace(
    '</head>',
    `<meta name="rml-build" content="${marker}"></head>`,
  );
  // the new build's policy hashes its own inline script (the preloader names the new files)
  writeFileSync(join(dir, 'index.html'), withCsp(html));
  const sw = readFileSync(join(dir, 'sw.js'), 'utf8');
  const sw2 = rename(sw).replace(/(url:\s*"index\.html",\s*revision:\s*")[^"]+"/, `$1${marker}"`);
  expect(sw2, 'the service worker precaches index.html with a revision').not.toBe(rename(sw));
  writeFileSync(join(dir, 'sw.js'), sw2);
  return marker;
}

test('offline and a deploy: one visit caches the whole build, a scene never opened works with the host gone; after a deploy Reload moves its own tab to the new build with its typed answer, the other keeps its work', async ({
  page,
  context,
}) => {
  test.setTimeout(360_000);
  const srv = await serveBuildCopy();
  const built = (p: Page) => p.locator('meta[name="rml-build"]');
  try {
    // tab A: a first visit (no worker controls it when it loads; the first install claims it), a
    // practice page with an answer typed and not checked
    await page.goto(`${srv.base}#/practice/q5?seed=3`);
    expect(await page.evaluate(() => navigator.serviceWorker.controller === null)).toBe(true);
    await page.getByTestId('answer-a').fill('12.5');
    // (the field let go: its blinking caret would keep the page from the quiet moment the
    // worker's registration waits for, up to its 30 s limit)
    await page.getByTestId('answer-a').blur();
    await waitForServiceWorker(page);
    // the web app manifest is linked once the worker registers (not in index.html), and is served
    const manifest = await page.evaluate(async () => {
      const href = document.querySelector<HTMLLinkElement>('link[rel="manifest"]')?.href;
      return href ? (((await (await fetch(href)).json()) as { name?: string }).name ?? null) : null;
    });
    expect(manifest).toBe('Render Math Lab');

    await test.step('with the host gone, the cache holds every build file and a scene never opened works', async () => {
      srv.setDown(true);
      expect(
        await fetch(srv.base).then(
          () => 'reached',
          () => 'failed',
        ),
      ).toBe('failed');
      const cached = await page.evaluate(async () => {
        const urls: string[] = [];
        for (const name of await caches.keys())
          for (const req of await (await caches.open(name)).keys()) urls.push(new URL(req.url).pathname);
        return urls;
      });
      const missing = appFiles().filter((f) => !cached.some((u) => u.endsWith(`/app/${f}`)));
      expect(missing, 'build files missing from the offline cache').toEqual([]);
    });

    // tab B: a scene never opened, loaded with the host gone (controlled by the worker from its
    // start): its plots, 3D view, workers and formulas all come from the cache (every other
    // route's files are in the same cache, checked above)
    const tabB = await context.newPage();
    const errors: string[] = [];
    tabB.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    tabB.on('pageerror', (e) => errors.push(e.message));
    await tabB.goto(`${srv.base}#/hemisphere`);
    await expect(tabB.locator('main#main')).toBeVisible({ timeout: 60000 });
    await expect(tabB.locator('.loading')).toHaveCount(0, { timeout: 60000 });
    const keyReadout = tabB.getByTestId(key('hemisphere').keyReadout!).first();
    await expect(keyReadout).toHaveAttribute('data-value', /^-?\d/, { timeout: 60000 });
    // bring every lazy view (plots, 3D, formulas) on screen so their chunks load
    await settleLazyViews(tabB);
    await expect(tabB.locator('.notice-error')).toHaveCount(0);
    await expect(tabB.getByText('could not be drawn')).toHaveCount(0);
    expect(errors, 'console errors on #/hemisphere offline').toEqual([]);
    expect(await tabB.evaluate(() => navigator.serviceWorker.controller !== null)).toBe(true);
    srv.setDown(false);

    for (const p of [page, tabB])
      await p.evaluate(() => {
        const w = window as unknown as { __oldPage: boolean; __taken: Promise<boolean> };
        w.__oldPage = true; // gone if the page reloads
        w.__taken = new Promise((ok) =>
          navigator.serviceWorker.addEventListener('controllerchange', () => ok(true), { once: true }),
        );
      });

    const marker = deployRenamedBuild(srv.dir);
    // the browser's own update check (on a navigation, or periodically), from the first-visit tab
    await page.evaluate(() =>
      navigator.serviceWorker.getRegistration().then((r) => r?.update().then(() => undefined)),
    );
    const notice = page.getByTestId('update-notice');
    await expect(notice).toBeVisible({ timeout: 60000 });
    await expect(tabB.getByTestId('update-notice')).toBeVisible({ timeout: 60000 });
    expect(await built(page).count()).toBe(0);
    // nobody was reloaded but by their reader: A's typed answer is still there
    expect(await page.evaluate(() => (window as unknown as { __oldPage?: boolean }).__oldPage)).toBe(true);
    await expect(page.getByTestId('answer-a')).toHaveValue('12.5');

    // A's reader clicks Reload: A lands on the new build (it had no controller when it loaded),
    // with the answer it had typed (A is brought to the front, as a reader's click would: a click
    // waits for the button to hold still over two frames, and a tab behind another may draw none)
    await page.bringToFront();
    await notice.getByRole('button', { name: 'Reload' }).click();
    await expect(built(page)).toHaveAttribute('content', marker, { timeout: 60000 });
    await expect(page.getByTestId('answer-a')).toHaveValue('12.5');
    await expect(page.getByTestId('verdict-a')).toHaveCount(0);
    await expect(page.getByTestId('update-notice')).toHaveCount(0);

    // B is now controlled by the new build's worker and was not reloaded (its reader did not
    // ask): it still runs the old build, offering Reload
    expect(await tabB.evaluate(() => (window as unknown as { __taken: Promise<boolean> }).__taken)).toBe(
      true,
    );
    expect(await tabB.evaluate(() => (window as unknown as { __oldPage?: boolean }).__oldPage)).toBe(true);
    expect(await built(tabB).count()).toBe(0);
    await expect(tabB.getByTestId('update-notice').getByRole('button', { name: 'Reload' })).toBeEnabled();
    await expect(keyReadout).toHaveAttribute('data-value', /^-?\d/);

    // B's reader opens another scene, whose chunk went with the old build: the page reloads onto
    // the new build at that address instead of failing
    await tabB.evaluate(() => {
      window.location.hash = '#/monte-carlo';
    });
    await expect(built(tabB)).toHaveAttribute('content', marker, { timeout: 60000 });
    await expect(tabB).toHaveURL(/#\/monte-carlo$/);
    await expect(tabB.getByTestId('exact').first()).toHaveAttribute('data-value', /^-?\d/, {
      timeout: 60000,
    });
    await expect(tabB.locator('.notice-error')).toHaveCount(0);
    await tabB.close();
  } finally {
    await srv.stop().catch(() => undefined);
    rmSync(srv.dir, { recursive: true, force: true });
  }
});

// The policy is a meta element of index.html (scripts/csp.ts), so every browser test runs under
// it and fails on the console error a violation logs; here: the policy is there, and an attacker's
// inline script and inline handler are refused.
test('the build’s Content-Security-Policy refuses injected script and handlers, and says so', async ({
  page,
  context,
  consoleErrors,
}) => {
  await recordCspViolations(context);
  await page.goto('./#/practice/q1?seed=17');
  await expect(page.locator('main#main')).toBeVisible();
  const meta = await page.locator('meta[http-equiv="Content-Security-Policy"]').getAttribute('content');
  expect(meta).toMatch(/script-src 'self' 'sha256-/);
  expect(await cspViolations(page)).toEqual([]);
  const injected = await injectScript(page);
  expect(injected.ran).toEqual([]);
  expect(injected.reported).toEqual(['script-src-elem inline', 'script-src-attr inline']);
  // (the browser logs each refusal as a console error: those two are expected)
  const refused = consoleErrors.filter((e) => INJECTION_REFUSED.test(e));
  expect(refused).toHaveLength(2);
  consoleErrors.splice(0, consoleErrors.length, ...consoleErrors.filter((e) => !INJECTION_REFUSED.test(e)));
});
