/**
 * Browser tests of the shell: home page, routes, the URL-parameter notice, embed and classroom
 * modes, share links, accessibility of the home page, and what `#/` downloads (axe on every scene:
 * catalogue.spec.ts). The app is served from a sub-folder (/app/) to prove the static build works
 * from any folder.
 */
import { test, expect, openScene, readout } from './fixtures';
import { SCENES, sceneSchema } from './sceneSchemas';

const ROUTES = SCENES.map((s) => s.path);

test('home lists the six exam questions, each linking to its scene', async ({ page }) => {
  await openScene(page, '#/');
  await expect(page.getByRole('heading', { level: 1 })).toBeVisible();
  const cards = page.locator('.question-card');
  await expect(cards).toHaveCount(6);
  for (let i = 1; i <= 6; i++) await expect(cards.nth(i - 1)).toContainText(`Q${i}`);
  // every built scene's card links to its route; none is a dead link
  const hrefs = await page
    .locator('.question-card h2 a')
    .evaluateAll((as) => as.map((a) => a.getAttribute('href')));
  for (const h of hrefs)
    expect(
      ROUTES.some((r) => h!.startsWith(`#${r}`)),
      h!,
    ).toBe(true);
});

test('#/ downloads no three.js, Plotly, mathjs, KaTeX or scene code', async ({ page }) => {
  const requests: string[] = [];
  page.on('request', (r) => requests.push(r.url()));
  await openScene(page, '#/');
  await page.waitForLoadState('networkidle');
  const js = requests.filter((u) => u.endsWith('.js'));
  expect(js.length).toBeGreaterThan(0);
  for (const u of requests) {
    expect(u, 'heavy library requested by #/').not.toMatch(/vendor-(three|plotly|katex)/);
    expect(u, 'scene chunk requested by #/').not.toMatch(/scene-/);
  }
  // #/ downloads only the entry chunk and the bundler runtime: no mathjs (which has no named
  // chunk), no worker, no shared scene code. The budget script checks the same files' size and
  // scans them for each library's signature.
  // After the page has loaded, the service-worker registration (a ~3 kB lazy chunk and
  // workbox-window) and the worker itself (sw.js, which precaches the build off the page) load too.
  const names = js.map((u) => new URL(u).pathname.split('/').pop()!);
  const swFiles = /^(pwa-[\w-]+|workbox-window\.prod\.es5-[\w-]+|sw|workbox-[\w-]+)\.js$/;
  // The entry is index-*.js with what it imports statically (the bundler may split a module the
  // entry shares with lazy chunks into a chunk of its own; it is still entry code, counted by the
  // budget script): read those imports from the entry script itself.
  const entryUrl = js.find((u) => /\/index-[\w-]+\.js$/.test(u));
  expect(entryUrl, 'the entry script').toBeTruthy();
  // (and what those import statically in turn: a chunk shared by the entry's own chunks)
  const staticImports = new Set<string>();
  const pending = [entryUrl!];
  while (pending.length) {
    const url = pending.pop()!;
    const src = await (await page.request.get(url)).text();
    for (const m of src.matchAll(/(?:^|[;\n}])\s*import\s*(?:[\w*${}\s,]+from\s*)?["']\.\/([^"']+\.js)["']/g))
      if (!staticImports.has(m[1])) {
        staticImports.add(m[1]);
        pending.push(new URL(m[1], url).href);
      }
  }
  for (const n of names)
    if (!swFiles.test(n) && !staticImports.has(n))
      expect(n, `unexpected script ${n} on #/`).toMatch(/^(index|rolldown-runtime)-[\w-]+\.js$/);
});

test('an unknown route says so instead of showing a blank page', async ({ page }) => {
  await openScene(page, '#/no-such-scene?x=1');
  await expect(page.getByRole('heading', { name: 'Page not found' })).toBeVisible();
  await expect(page.getByRole('link', { name: /list of scenes/ })).toBeVisible();
});

test('embed=1 hides the site chrome and links back to the full app', async ({ page }) => {
  await openScene(page, '#/texture?embed=1');
  await expect(page.locator('.site-header')).toHaveCount(0);
  await expect(page.locator('.site-footer')).toHaveCount(0);
  const back = page.getByRole('link', { name: /Open in Render Math Lab/ });
  await expect(back).toBeVisible();
  expect(await back.getAttribute('href')).not.toContain('embed=1');
  await openScene(page, '#/texture');
  await expect(page.locator('.site-header')).toBeVisible();
});

test('an embedded scene posts its height to the host page', async ({ page, baseURL }) => {
  await page.setContent(
    `<script>window.msgs = []; addEventListener('message', (e) => msgs.push(e.data));</script>
     <iframe id="f" title="scene" src="${baseURL}#/texture?embed=1" style="width:800px;height:300px"></iframe>`,
  );
  type Msg = { type: string; height: number };
  const lastHeight = () =>
    page.evaluate(
      () =>
        (window as unknown as { msgs: Msg[] }).msgs
          .filter((m) => m && m.type === 'render-math-lab:height')
          .at(-1)?.height ?? 0,
    );
  // the first message may come while the scene is still loading; the page posts again when its
  // height changes, so the last height reported grows to the loaded scene's (well over 300 px)
  await expect.poll(lastHeight, { timeout: 20000 }).toBeGreaterThan(300);
  // and it matches the embedded document's real height
  const frame = page.frameLocator('#f');
  await expect(frame.getByTestId('copy-link')).toBeVisible();
  // (the page may still be growing: sections below the first screen mount in idle time; the
  // posted height is rounded up, scrollHeight to the nearest pixel)
  const gap = async () =>
    Math.abs(
      (await lastHeight()) - (await page.frames()[1].evaluate(() => document.documentElement.scrollHeight)),
    );
  await expect.poll(gap, { timeout: 20000 }).toBeLessThanOrEqual(1);
});

test('Copy link and Copy embed code produce URLs that restore the same state', async ({ page, context }) => {
  await openScene(page, '#/texture?u=0.7&v=0.3&wrap=repeat');
  const before = await readout(page, 'bilinear');
  await page.getByTestId('copy-link').click();
  const link = await page.getByTestId('share-text').inputValue();
  expect(link).toMatch(/#\/texture\?/);
  expect(link).toContain('u=0.7');
  expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(link);
  const other = await context.newPage();
  await other.goto(link);
  await expect(other.getByTestId('bilinear')).toHaveAttribute('data-value', before);
  await other.close();

  await page.getByTestId('copy-embed').click();
  const code = await page.getByTestId('share-text').inputValue();
  const src = /src="([^"]+)"/.exec(code)![1].replace(/&amp;/g, '&');
  expect(src).toContain('embed=1');
  const embedded = await context.newPage();
  await embedded.goto(src);
  await expect(embedded.getByTestId('bilinear')).toHaveAttribute('data-value', before);
  await expect(embedded.locator('.site-header')).toHaveCount(0);
  await embedded.close();
});

test('present=1 enlarges type and offers keyboard shortcuts', async ({ page }) => {
  await openScene(page, '#/?present=1');
  await expect(page.locator('html')).toHaveClass(/present/);
  const size = await page.evaluate(() => parseFloat(getComputedStyle(document.documentElement).fontSize));
  expect(size).toBeGreaterThanOrEqual(20);
  await page.keyboard.press('?');
  const dialog = page.getByRole('dialog', { name: 'Keyboard shortcuts' });
  await expect(dialog).toBeVisible();
  // the home page has nothing to play: the list shows only the keys that do something here
  await expect(dialog).toContainText('show this list');
  await expect(dialog).not.toContainText('play / pause');
  await dialog.getByRole('button', { name: 'Close' }).click();
  await expect(dialog).toHaveCount(0);
});

test('part= lands on the exam part and next/previous question links follow the exam', async ({ page }) => {
  await openScene(page, '#/texture?part=3b');
  // the scene may not have drawn its parts yet in older builds: the link must never break the page
  await expect(page.getByTestId('next-question')).toHaveAttribute('href', /#\/monte-carlo\?.*part=4a/);
  await expect(page.getByTestId('prev-question')).toHaveAttribute('href', /#\/hemisphere\?.*part=2a/);
  await openScene(page, '#/texture?part=9z');
  await expect(page.getByTestId('param-notice')).toContainText('part');
});

test('theme=dark and theme=light override the system theme', async ({ page }) => {
  await page.emulateMedia({ colorScheme: 'light' });
  await openScene(page, '#/?theme=dark');
  await expect(page.locator('html')).toHaveAttribute('data-theme', 'dark');
  await page.emulateMedia({ colorScheme: 'dark' });
  await openScene(page, '#/texture');
  await expect(page.locator('html')).toHaveAttribute('data-theme', 'dark');
  await page.goto('./#/texture?theme=light');
  await expect(page.locator('html')).toHaveAttribute('data-theme', 'light');
});

test('service workers blocked (as in automated browsers): the registration settles with no error', async ({
  page,
}) => {
  // the page registers its worker once loaded and quiet; record what the registration gives
  await page.addInitScript(() => {
    const sw = navigator.serviceWorker;
    if (!sw) return;
    const register = sw.register.bind(sw);
    const w = window as unknown as { __swSettled?: string };
    sw.register = (...a: Parameters<ServiceWorkerContainer['register']>) => {
      const p = register(...a);
      p.then(
        (r) => (w.__swSettled = r ? 'registered' : 'nothing'),
        () => (w.__swSettled = 'refused'),
      );
      return p;
    };
  });
  await openScene(page, '#/texture');
  await expect
    .poll(() => page.evaluate(() => (window as unknown as { __swSettled?: string }).__swSettled), {
      timeout: 60_000,
    })
    .toBeTruthy();
  // the page's own handling runs after the recorder's: give it a task, then the fixture checks that
  // no console error or uncaught error (such as reading .waiting of nothing) was seen
  await page.evaluate(() => new Promise((r) => setTimeout(r, 0)));
  await expect(page.locator('link[rel="manifest"]')).toHaveCount(1);
});

// The timeline is the shared one (src/ui), the same on every scene; catalogue.spec.ts runs the
// timeline's behaviours on each scene of the catalogue.
test('play=1 plays: a link asking to play from the end (or at the default t) plays from the start', async ({
  page,
}) => {
  const scene = SCENES.find((s) => s.id === 'ray-sphere')!;
  const t = (await sceneSchema(scene.id)).t;
  expect(t?.kind === 'number' && t.max !== undefined, 'the scene has a timeline position t').toBe(true);
  const tMax = t?.kind === 'number' ? t.max : undefined;
  for (const hash of [`#${scene.path}?play=1`, `#${scene.path}?play=1&t=${tMax}`]) {
    await openScene(page, hash);
    const tl = page.getByTestId('timeline').first();
    // playing: the transport says so, and the link keeps play=1 while it plays
    await expect(tl, hash).toHaveAttribute('data-playing', '1');
    await expect.poll(() => page.evaluate(() => window.location.hash), { message: hash }).toContain('play=1');
    await tl.getByRole('button', { name: /Pause/ }).click();
    await expect(tl, hash).toHaveAttribute('data-playing', '0');
  }
});
