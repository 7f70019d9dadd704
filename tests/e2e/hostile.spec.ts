/**
 * Hostile input, kept fixed:
 *  - a URL corpus on every route: hostile values (empty, NaN, ±Infinity, 1e400, 100k characters,
 *    unicode/RTL marks, broken percent-escapes, wrong arity, deeply nested calls) given to all of
 *    a route's parameters at once, each parameter a different one, rotated over two hash changes
 *    (the scene stays loaded), then a prototype name on every parameter, then an unknown parameter
 *    and a repeated one: zero console errors (fixture), a working scene, and a notice naming every
 *    non-text parameter whose value could not be used. Every parameter of every scene against every
 *    value of the corpus is read in tests/kit/sceneParamsHostile.test.ts; here the page shows it;
 *  - the fuzz mode (`fuzz=1&seed=…&fuzzn=…`) on every route, fixed seed, a few hundred actions.
 * Routes come from the catalogue (src/kit/catalogue.ts) plus EXTRA_ROUTES, parameter names and
 * kinds from each scene's schema (its params.ts), so new scenes are covered without editing this file.
 */
import { test, expect, openScene, settle } from './fixtures';
import { SCENES, sceneParams } from './sceneSchemas';
import type { SceneId } from '../../src/kit/catalogue';
import type { Page } from '@playwright/test';

type Route = { path: string; id: SceneId | null; params?: { name: string; kind: string }[] };

/** Routes that are not scenes, with the parameters each takes. */
const EXTRA_ROUTES: Route[] = [
  { path: '/', id: null, params: [] },
  { path: '/guide', id: null, params: [] },
  { path: '/practice', id: null, params: [] },
  { path: '/practice/q5', id: null, params: [{ name: 'seed', kind: 'number' }] },
  { path: '/practice/q1', id: null, params: [{ name: 'seed', kind: 'number' }] },
  {
    path: '/practice/sheet',
    id: null,
    params: [
      { name: 'seed', kind: 'number' },
      { name: 'q', kind: 'list' },
      { name: 'count', kind: 'number' },
    ],
  },
];

/** Every scene of the catalogue; its parameters come from its schema when the test runs. */
const SCENE_ROUTES: Route[] = SCENES.map((sc) => ({ path: sc.path, id: sc.id }));

const ROUTES = [...SCENE_ROUTES, ...EXTRA_ROUTES];

const NESTED = `${'exp('.repeat(60)}x${')'.repeat(60)}`;
/** [label, raw text put into the query as is (already URL-encoded where needed)]. */
// Prototype names are not in it: the per-parameter pass below puts one on each parameter, and
// tests/kit/sceneParamsHostile.test.ts reads every scene's schema with every value of this corpus
// and the prototype names.
const CORPUS: [string, string][] = [
  ['empty', ''],
  ['NaN', 'NaN'],
  ['Infinity', 'Infinity'],
  ['-Infinity', '-Infinity'],
  ['1e400', '1e400'],
  ['100k characters', 'x'.repeat(100_000)],
  ['unicode and RTL marks', encodeURIComponent('\u202Eθ\u200F😀\u200E')],
  ['broken percent-escapes', '%E0%A4%A%ZZ%'],
  ['wrong arity', '1,2'],
  ['deeply nested calls', encodeURIComponent(NESTED)],
];

async function expectWorkingScene(page: Page, label: string) {
  await expect(page.locator('main#main')).toBeVisible();
  await expect(page.locator('.loading')).toHaveCount(0);
  await expect(
    page.getByText('Something in this scene went wrong'),
    `error panel after ${label}`,
  ).toHaveCount(0);
}

/**
 * How many hash changes the corpus is rotated over (parameter j gets value (j + 3i) mod 10 in
 * change i); every parameter against every value is tests/kit/sceneParamsHostile.test.ts's.
 */
const ROTATIONS = 2;

/** The whole corpus on one route of the open page (reached by a hash change: the app stays loaded). */
async function corpusOn(page: Page, route: Route): Promise<void> {
  const params = route.params ?? (route.id ? await sceneParams(route.id) : []);
  await openScene(page, `#${route.path}`);
  // scrolled through once, so every section (lazy libraries, plots) is mounted and takes the input
  for (let y = 0; y <= 4; y++) {
    await page.evaluate((f) => window.scrollTo(0, f * document.body.scrollHeight), y / 4);
    await settle(page);
  }
  await page.evaluate(() => window.scrollTo(0, 0));
  const notice = page.getByTestId('param-notice').first();
  const go = async (q: string) => {
    await page.evaluate((h) => {
      window.location.hash = h;
    }, `#${route.path}?${q}`);
    await settle(page);
  };
  // theme (a shell parameter, on every route) never takes a hostile value silently either
  const all = [...params, { name: 'theme', kind: 'enum' }];
  for (let i = 0; i < ROTATIONS; i++) {
    const given = all.map((p, j) => ({ p, value: CORPUS[(j + 3 * i) % CORPUS.length]! }));
    await go(given.map(({ p, value }) => `${p.name}=${value[1]}`).join('&'));
    const label = `change ${i}: ${given.map(({ p, value }) => `${p.name}=${value[0]}`).join(', ')}`;
    await expectWorkingScene(page, label);
    // every non-text parameter that cannot use its value is named in the notice
    // (a list takes '' as its default and '1,2' as two numbers: those are usable)
    const mustName = given.filter(
      ({ p, value }) =>
        p.kind !== 'string' && !(p.kind === 'list' && (value[1] === '' || value[1] === '1,2')),
    );
    await expect(notice, `notice after ${label} on ${route.path}`).toBeVisible();
    const text = (await notice.textContent()) ?? '';
    const named = route.id ? await notice.locator('li code').allTextContents() : null;
    for (const { p, value } of mustName) {
      const what = `${route.path}: ${p.name}=${value[0]} is named`;
      if (named && p.name !== 'theme') expect(named, what).toContain(p.name);
      else expect(text, what).toContain(p.name);
    }
  }
  // a prototype name on every parameter: the URL never carries a function's source
  await go(params.map((p) => `${p.name}=toString`).join('&'));
  await expectWorkingScene(page, 'toString');
  expect(await page.evaluate(() => window.location.href)).not.toMatch(/native%20code|native code/);
  // an unknown parameter and a repeated one are named
  await go('bogus=1&theme=dark&theme=light');
  await expect(notice).toBeVisible();
  await expect(notice).toContainText('bogus');
  await expect(notice).toContainText('theme');
  await expectWorkingScene(page, 'bogus=1, theme twice');
}

for (const [title, routes] of [
  ['every scene', SCENE_ROUTES],
  ['every other page', EXTRA_ROUTES],
] as const) {
  test(`URL corpus on ${title}: hostile values, prototype names, unknown and repeated parameters`, async ({
    page,
  }) => {
    test.setTimeout(300_000);
    for (const route of routes) await test.step(route.path, () => corpusOn(page, route));
  });
}

// Sized for the whole spec's fuzz part to stay near 2 minutes on a loaded 2-core machine (~25 s a route);
// run more by hand: #/<route>?fuzz=1&fuzzseed=N (unbounded) or &fuzzn=1000.
const FUZZ_ACTIONS = 80;

// The fuzzer is in development and test builds only (a production build has none): these run on a
// build made with VITE_RML_FUZZ=1 (npm run e2e:fuzz).
const FUZZ_BUILD = process.env.VITE_RML_FUZZ === '1';

test.describe('fuzz mode', () => {
  // skipped here, before any page opens, on a build without the fuzzer
  test.skip(!FUZZ_BUILD, 'needs a build with the fuzzer: npm run e2e:fuzz');
  for (const route of ROUTES) {
    test(`${route.path}: ${FUZZ_ACTIONS} seeded actions, no error`, async ({ page }) => {
      test.setTimeout(120_000);
      await openScene(page, `#${route.path}?fuzz=1&fuzzseed=17&fuzzn=${FUZZ_ACTIONS}`);
      await expect(page.locator('.fuzz-panel')).toBeVisible();
      await expect
        .poll(
          async () =>
            page.evaluate(
              () => (window as unknown as { __rmlFuzz?: { running: boolean } }).__rmlFuzz?.running ?? true,
            ),
          { timeout: 100_000, intervals: [500] },
        )
        .toBe(false);
      const state = await page.evaluate(() => {
        const f = (window as unknown as { __rmlFuzz: { actions: number; errors: string[]; log: string[] } })
          .__rmlFuzz;
        return { actions: f.actions, errors: f.errors, log: f.log };
      });
      expect(state.actions).toBe(FUZZ_ACTIONS);
      expect(state.errors, `errors while fuzzing (last actions: ${state.log.join(' | ')})`).toEqual([]);
      await expectWorkingScene(page, 'fuzzing');
    });
  }
});
