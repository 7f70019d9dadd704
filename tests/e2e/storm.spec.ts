/**
 * A change storm at a large sample count for a scene whose seeded results come from a worker:
 * #/monte-carlo opened with each count parameter at a tenth of the maximum its schema allows
 * (10⁶ samples: enough that a run outlasts the next change), then changed as fast as the page
 * takes them: a new seed each time, and every choice parameter (point set, pdf, …) cycling
 * through its values. Results of superseded changes can still come back while the next change is
 * under way. The last change must win: once the storm is over, the page shows exactly what a fresh
 * load of the final URL shows.
 *
 * Elsewhere: the hemisphere's storm through every way its address changes, at n = 200 000, in
 * address-storm.spec.ts; that the hemisphere's and the area light's worker jobs give the model's
 * numbers for their arguments, in tests/scenes/hemisphere/jobs.test.ts and
 * tests/scenes/area-light/jobs.test.ts. How long the main thread's tasks take during a storm is a
 * measurement, not a test: `npm run perf:longtasks` (scripts/perf-longtasks.mjs).
 */
import { test, expect, openScene, readout, waitForReadout } from './fixtures';
import { SCENES, maxCountsQuery, sceneSchema } from './sceneSchemas';
import type { SceneId } from '../../src/kit/catalogue';
import type { Page } from '@playwright/test';

const CHANGES = 16;

/** The scene stormed, and a readout whose value depends on the seed and comes from its worker. */
const SEEDED_READOUT: Partial<Record<SceneId, string>> = {
  'monte-carlo': 'estimate',
};

/**
 * `n` changes from `first` on, each once the page has taken the last (a frame and a task later):
 * change i sets seed = i and every choice parameter (`cycle`: name → values) to its (i mod k)-th
 * value, so each sampler, point set or strategy also runs for the first time (cold code) mid-storm.
 */
async function storm(
  page: Page,
  base: string,
  cycle: [string, readonly string[]][],
  first: number,
  n: number,
): Promise<string> {
  return page.evaluate(
    async ({ base, cycle, first, n }) => {
      for (let i = first; i < first + n; i++) {
        const q = cycle.map(([name, values]) => `&${name}=${values[i % values.length]}`).join('');
        window.location.hash = `${base}seed=${i}${q}`;
        await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
      }
      return window.location.hash;
    },
    { base, cycle, first, n },
  );
}

for (const scene of SCENES.filter((s) => SEEDED_READOUT[s.id])) {
  test(`${scene.path} at large counts: after a storm of changes the last change wins`, async ({
    page,
    browser,
  }) => {
    test.setTimeout(240_000);
    const schema = await sceneSchema(scene.id);
    test.skip(!('seed' in schema), 'no seed to change');
    const cycle = Object.entries(schema).flatMap(([name, spec]): [string, readonly string[]][] =>
      spec.kind === 'enum' ? [[name, spec.values]] : [],
    );
    const counts = await maxCountsQuery(scene.id, 0.1);
    const hash = `#${scene.path}?${counts}`;
    const id = SEEDED_READOUT[scene.id]!;

    await openScene(page, hash);
    const last = await storm(page, `${hash}${counts ? '&' : ''}`, cycle, 2, CHANGES);
    expect(last).toContain(`seed=${CHANGES + 1}`);

    // the same URL loaded afresh in its own page: its settled value is the one the storm must end on
    const fresh = await browser.newPage();
    await openScene(fresh, last);
    // (a worker's readout says "none" until its run is done)
    const expected = await waitForReadout(fresh, id, (v) => v !== 'none', 120_000);
    await fresh.close();
    await expect.poll(() => readout(page, id), { timeout: 120_000 }).toBe(expected);
    await expect(page.getByText('Something in this scene went wrong')).toHaveCount(0);
  });
}
