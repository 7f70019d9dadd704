/**
 * Browser tests of the shell: the home page and what `#/` downloads, classroom type and the `?`
 * list there, theme=, an unknown route, and on one scene embed=1, part= and the next/previous
 * question links, play=1, Copy link and Copy embed code (the pasted snippet sizes its iframe and
 * restores the state). The service worker's registration in a browser: offline.spec.ts (where
 * registration is blocked, as in many automated browsers, it settles with nothing or is refused:
 * tests/app/pwa.test.ts). Axe on every scene: catalogue.spec.ts;
 * the host page's height messages: host-api.spec.ts. The app is served from a sub-folder (/app/)
 * to prove the static build works from any folder.
 */
import { test, expect, openScene, readout, settle } from './fixtures';
import { SCENES, sceneSchema } from './sceneSchemas';

const ROUTES = SCENES.map((s) => s.path);

test('home: #/ downloads no heavy library and lists the six questions; present=1, theme= and an unknown route', async ({
  page,
}) => {
  test.setTimeout(120_000);
  const requests: string[] = [];
  page.on('request', (r) => requests.push(r.url()));
  await page.emulateMedia({ colorScheme: 'light' });
  await openScene(page, '#/');

  await test.step('#/ downloads no three.js, mathjs, KaTeX, chart or scene code', async () => {
    await page.waitForLoadState('networkidle');
    const js = requests.filter((u) => u.endsWith('.js'));
    expect(js.length).toBeGreaterThan(0);
    for (const u of requests) {
      expect(u, 'heavy library requested by #/').not.toMatch(/vendor-(three|katex)/);
      expect(u, 'scene chunk requested by #/').not.toMatch(/scene-/);
      expect(u, 'the plots’ chart requested by #/').not.toMatch(/\/draw-[^/]*\.js$/);
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
      for (const m of src.matchAll(
        /(?:^|[;\n}])\s*import\s*(?:[\w*${}\s,]+from\s*)?["']\.\/([^"']+\.js)["']/g,
      ))
        if (!staticImports.has(m[1])) {
          staticImports.add(m[1]);
          pending.push(new URL(m[1], url).href);
        }
    }
    for (const n of names)
      if (!swFiles.test(n) && !staticImports.has(n))
        expect(n, `unexpected script ${n} on #/`).toMatch(/^(index|rolldown-runtime)-[\w-]+\.js$/);
  });

  await test.step('home lists the six exam questions, each linking to its scene', async () => {
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

  await test.step('present=1 enlarges type and offers keyboard shortcuts', async () => {
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

  await test.step('theme=dark and theme=light override the system theme', async () => {
    await openScene(page, '#/?theme=dark');
    await expect(page.locator('html')).toHaveAttribute('data-theme', 'dark');
    await page.emulateMedia({ colorScheme: 'dark' });
    await openScene(page, '#/');
    await expect(page.locator('html')).toHaveAttribute('data-theme', 'dark');
    await openScene(page, '#/?theme=light');
    await expect(page.locator('html')).toHaveAttribute('data-theme', 'light');
  });

  await test.step("before any script loads, the page is in the link's theme and classroom type", async () => {
    // scripts from the network blocked: only index.html's own (inline) ones run
    const bare = await page.context().newPage();
    await bare.route(/\.js(\?|$)/, (r) => r.abort());
    await bare.goto('./#/area-light?theme=dark&present=1');
    await expect(bare.locator('html')).toHaveAttribute('data-theme', 'dark');
    await expect(bare.locator('html')).toHaveClass(/present/);
    const look = await bare.evaluate(() => ({
      bg: getComputedStyle(document.body).backgroundColor,
      rootSize: getComputedStyle(document.documentElement).fontSize,
    }));
    // the dark theme's background (no light frame before the app's code), classroom type
    expect(look).toEqual({ bg: 'rgb(21, 23, 27)', rootSize: '22px' });
    await bare.close();
  });

  await test.step('the shell stylesheet is inline: a scene and its lazy folds never download it', async () => {
    const css: string[] = [];
    const listen = (r: { url(): string }) => {
      if (/\/index-[\w-]+\.css$/.test(r.url())) css.push(r.url());
    };
    page.on('request', listen);
    await openScene(page, '#/area-light?open=convergence');
    await expect(page.locator('.fold-loading')).toHaveCount(0);
    page.off('request', listen);
    expect(css).toEqual([]);
    // and its rules apply: the header's colours come from it
    const bg = await page.locator('.site-header').evaluate((h) => getComputedStyle(h).backgroundColor);
    expect(bg).not.toBe('rgba(0, 0, 0, 0)');
  });

  await test.step('an unknown route says so instead of showing a blank page', async () => {
    await openScene(page, '#/no-such-scene?x=1');
    await expect(page.getByRole('heading', { name: 'Page not found' })).toBeVisible();
    await expect(page.getByRole('link', { name: /list of scenes/ })).toBeVisible();
  });
});

test('a scene: embed=1, part= and next/previous, play=1, Copy link and the pasted embed code restore the state', async ({
  page,
  context,
}) => {
  test.setTimeout(180_000);
  await test.step('embed=1 hides the site chrome and links back to the full app', async () => {
    await openScene(page, '#/texture?embed=1');
    await expect(page.locator('.site-header')).toHaveCount(0);
    await expect(page.locator('.site-footer')).toHaveCount(0);
    const back = page.getByRole('link', { name: /Open in Render Math Lab/ });
    await expect(back).toBeVisible();
    expect(await back.getAttribute('href')).not.toContain('embed=1');
    await openScene(page, '#/texture');
    await expect(page.locator('.site-header')).toBeVisible();
  });

  await test.step('part= lands on the exam part; next/previous question links follow the exam', async () => {
    await openScene(page, '#/texture?part=3b');
    await expect(page.getByTestId('next-question')).toHaveAttribute('href', /#\/monte-carlo\?.*part=4a/);
    await expect(page.getByTestId('prev-question')).toHaveAttribute('href', /#\/hemisphere\?.*part=2a/);
    await openScene(page, '#/texture?part=9z');
    await expect(page.getByTestId('param-notice')).toContainText('part');
  });

  // The timeline is the shared one (src/ui), the same on every scene; catalogue.spec.ts runs the
  // timeline's behaviours (reduced motion, Play/Pause, the paused link) on each scene.
  await test.step('play=1 plays: a link asking to play from the end (or at the default t) plays from the start', async () => {
    const t = (await sceneSchema('texture')).t;
    expect(t?.kind === 'number' && t.max !== undefined, 'the scene has a timeline position t').toBe(true);
    const tMax = t?.kind === 'number' ? t.max : undefined;
    for (const hash of ['#/texture?play=1', `#/texture?play=1&t=${tMax}`]) {
      await openScene(page, hash);
      const tl = page.getByTestId('timeline').first();
      // playing: the transport says so, and the link keeps play=1 while it plays
      await expect(tl, hash).toHaveAttribute('data-playing', '1');
      await expect
        .poll(() => page.evaluate(() => window.location.hash), { message: hash })
        .toContain('play=1');
      await tl.getByRole('button', { name: /Pause/ }).click();
      await expect(tl, hash).toHaveAttribute('data-playing', '0');
    }
  });

  await openScene(page, '#/texture?u=0.7&v=0.3&wrap=repeat');
  const before = await readout(page, 'bilinear');

  await test.step('Copy link gives a URL that restores the same state', async () => {
    await page.getByTestId('copy-link').click();
    const link = await page.getByTestId('share-text').inputValue();
    expect(link).toMatch(/#\/texture\?/);
    expect(link).toContain('u=0.7');
    expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(link);
    // another state first, then the link: its state comes back
    await openScene(page, '#/texture');
    await expect(page.getByTestId('bilinear')).not.toHaveAttribute('data-value', before);
    await page.goto(link);
    await expect(page.getByTestId('bilinear')).toHaveAttribute('data-value', before);
  });

  await test.step('Copy embed code, pasted into a page as it is: the same state, embedded, its iframe sized to the content', async () => {
    await page.getByTestId('copy-embed').click();
    const code = await page.getByTestId('share-text').inputValue();
    const src = /src="([^"]+)"/.exec(code)![1].replace(/&amp;/g, '&');
    expect(src).toContain('embed=1');
    const id = /<iframe id="(rml-texture-[a-z0-9]+)"/.exec(code)?.[1];
    expect(id, code).toBeTruthy();
    expect(code).toContain('render-math-lab:height');
    expect(code).toContain(`getElementById('${id}')`);
    // (a page of its own: the app's Content-Security-Policy refuses the snippet's inline script)
    const host = await context.newPage();
    await host.setContent(`<!doctype html><body style="margin:0">${code}</body>`);
    const frame = host.frameLocator(`#${id}`);
    await expect(frame.getByTestId('bilinear').first()).toHaveAttribute('data-value', before, {
      timeout: 30_000,
    });
    await expect(frame.getByTestId('u-slider')).toHaveValue('0.7');
    await expect(frame.locator('.site-header')).toHaveCount(0);
    const f = host.frames().find((x) => x !== host.mainFrame() && x.url().includes('/app/'))!;
    const content = () =>
      f.evaluate(() =>
        Math.ceil(document.getElementById('root')!.getBoundingClientRect().bottom + window.scrollY),
      );
    await expect
      .poll(
        async () =>
          Math.abs(
            (await host.locator(`#${id}`).evaluate((el) => el.getBoundingClientRect().height)) -
              (await content()),
          ),
        { timeout: 20000 },
      )
      .toBeLessThanOrEqual(1);
    expect(await content()).toBeGreaterThan(720);
  });
});

interface Shift {
  value: number;
  nodes: string[];
}
type LayoutShiftEntry = PerformanceEntry & {
  value: number;
  hadRecentInput: boolean;
  sources?: Array<{ node?: Node | null }>;
};

// Each page that loads as a chunk of its own: the chunk's name, and what the page shows when it has
// finished its first screen.
const LAZY_PAGES: Array<{ hash: string; chunk: RegExp; ready: string }> = [
  { hash: '#/practice', chunk: /\/PracticeRoute-[\w-]+\.js$/, ready: 'main.practice-home' },
  { hash: '#/guide', chunk: /\/Guide-[\w-]+\.js$/, ready: 'main.guide' },
  { hash: '#/results', chunk: /\/ResultsRoute-[\w-]+\.js$/, ready: 'main.results-page[data-ready="1"]' },
  { hash: '#/accessibility', chunk: /\/AccessibilityPage-[\w-]+\.js$/, ready: 'main.accessibility' },
  { hash: '#/deck', chunk: /\/DeckPage-[\w-]+\.js$/, ready: 'main.deck-page' },
];

test('a page that loads as its own chunk: nothing moves when the chunk arrives (the footer stays below the first screen)', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await page.setViewportSize({ width: 412, height: 823 });
  // every layout shift from the page's start, with the class names of what moved
  await page.addInitScript(() => {
    const out: Shift[] = [];
    (window as unknown as { __shifts: Shift[] }).__shifts = out;
    new PerformanceObserver((list) => {
      for (const e of list.getEntries() as LayoutShiftEntry[])
        if (!e.hadRecentInput)
          out.push({
            value: e.value,
            nodes: (e.sources ?? []).map((x) => (x.node as Element | null)?.className ?? '?'),
          });
    }).observe({ type: 'layout-shift', buffered: true });
  });
  for (const p of LAZY_PAGES) {
    await test.step(p.hash, async () => {
      // the page's chunk is held back until its loading state has been painted
      let release = () => {};
      const held = new Promise<void>((r) => (release = r));
      await page.route(p.chunk, async (route) => {
        await held;
        await route.continue();
      });
      // a fresh load of the page, as a reader's first visit
      await page.goto('about:blank');
      await page.goto(`./${p.hash}`);
      await expect(page.locator('main.route-pending')).toBeVisible();
      await settle(page);
      release();
      await expect(page.locator(p.ready)).toBeVisible();
      await settle(page);
      const shifts = await page.evaluate(() => (window as unknown as { __shifts: Shift[] }).__shifts);
      const cls = shifts.reduce((s, e) => s + e.value, 0);
      expect(cls, JSON.stringify(shifts)).toBeLessThan(0.01);
      await page.unroute(p.chunk);
    });
  }
});
