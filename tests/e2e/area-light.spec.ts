/**
 * Browser tests of #/area-light: the readouts are the scene's model (computed here in Node from the
 * same link), a control and the timeline's step change them and write the link, the strategies'
 * fold mounts on open and the link reopens it; the floor images finish, follow the timeline, and
 * the FLIP the page shows is the FLIP of the two PNGs it downloads; the work done in workers (a
 * large n, the convergence and timing panels) arrives while the page answers.
 * Elsewhere: the estimators' and the solid angle's numbers are unit tests
 * (tests/scenes/area-light/cases.test.ts, runningEstimate.test.ts, tests/core/lights/); the exam's
 * worked steps and given samples are rendered in Node (tests/render/examParts.test.tsx); the page
 * as a whole, its parts in order and play, pause and the link's t are in catalogue.spec.ts; the
 * accessibility tree and the keyboard in area-light-a11y.spec.ts.
 */
import type { Download, Page } from '@playwright/test';
import { test, expect, openScene, readout, readoutNumber, waitForReadout } from './fixtures';
import { defaultValues, parseParams } from '../../src/kit/params';
import { schema } from '../../src/scenes/area-light/params';
import { animationFrame, animationLength, sampleRun } from '../../src/scenes/area-light/animation';
import { buildModel, estimateOne, TIMING_COUNTS } from '../../src/scenes/area-light/model';
import { STRATEGIES, STRATEGY_SHORT } from '../../src/scenes/area-light/strategies';
import { SYNC_MAX } from '../../src/scenes/area-light/model';
import type { LightStrategy } from '../../src/core/lights';
import { decodePng, rgbFromRgba8 } from '../../src/core/image/png';
import { flipErrorMap } from '../../src/core/image/flip';
import { poolError } from '../../src/core/image/pooling';

/** The model computed here, in Node, from a query string (the same parser as the app). */
function modelFor(query: string) {
  const values = { ...defaultValues(schema), ...parseParams(schema, new URLSearchParams(query)).values };
  return { values, model: buildModel(values) };
}

/** The running estimate of the animation at sample k, computed here. */
function animAt(query: string, k: number) {
  const { values, model } = modelFor(query);
  const run = sampleRun(model, values.strategy as LightStrategy, animationLength(values.n), values.seed);
  return animationFrame(run, k);
}

/**
 * The readouts equal the model's for a link. A link opened on the page that is already open
 * renders as a transition, a moment later: the readouts are read once the reference shows it.
 */
async function expectReadouts(page: Page, q: string) {
  const { values, model } = modelFor(q);
  await waitForReadout(page, 'reference', (v) => Number(v) === model.reference);
  expect(await readoutNumber(page, 'solid-angle'), q).toBe(model.solidAngle);
  const want = estimateOne(model, values.strategy as LightStrategy, values.n, values.seed);
  await waitForReadout(page, 'estimate', (v) => Number(v) === want.estimate);
  expect(await readoutNumber(page, 'stderr'), q).toBe(want.stderr);
  if (model.referenceOccluded === null) expect(await readout(page, 'reference-occluded'), q).toBe('none');
  else expect(await readoutNumber(page, 'reference-occluded'), q).toBe(model.referenceOccluded);
}

async function bytesOf(d: Download): Promise<Uint8Array> {
  const chunks: Buffer[] = [];
  for await (const c of await d.createReadStream()) chunks.push(c as Buffer);
  return new Uint8Array(Buffer.concat(chunks));
}

test('wiring: links, the strategy, the timeline’s step and the strategies’ fold give the model’s readouts', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await test.step('links: the exam’s light, an off-axis light and an occluded one', async () => {
    for (const q of [
      '',
      'p=0.2,-0.4,0&lc=0.9,0.3,1.5&ls=1.2,0.8&tilt=0&strategy=solid-angle&n=4096&seed=7',
      'occluder=1&strategy=cosine&n=4096&seed=3',
    ]) {
      await openScene(page, `#/area-light${q ? `?${q}` : ''}`);
      await expectReadouts(page, q);
    }
  });

  await test.step('choosing a strategy writes the link and the estimate is that strategy’s', async () => {
    await openScene(page, '#/area-light?n=2048&open=sampling');
    await expectReadouts(page, 'n=2048');
    await page.getByTestId('strategy').selectOption('cosine');
    await expect(page).toHaveURL(/strategy=cosine/);
    await expectReadouts(page, 'n=2048&strategy=cosine');
  });

  await test.step('the timeline: at sample k the running estimate is the model’s; a step adds one sample', async () => {
    const q = 'strategy=solid-angle&n=512&seed=21&t=100';
    await openScene(page, `#/area-light?${q}`);
    await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', '100');
    expect(await readoutNumber(page, 'anim-estimate')).toBeCloseTo(animAt(q, 100).estimate, 6);
    expect(await readoutNumber(page, 'anim-stderr')).toBeCloseTo(animAt(q, 100).stderr, 2);
    await page.getByTestId('timeline').getByRole('button', { name: /step/i }).click();
    await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', '101');
    expect(await readoutNumber(page, 'anim-estimate')).toBeCloseTo(animAt(q, 101).estimate, 6);
    await expect(page).toHaveURL(/[?&]t=101(&|$)/);
  });

  await test.step('beyond the exam, folded: the strategies’ table mounts on open, computes, and the link keeps it', async () => {
    const q = 'psize=0.3&ptilt=40&seed=9&occluder=1';
    await openScene(page, `#/area-light?${q}`);
    await expectReadouts(page, q);
    const { values, model } = modelFor(q);
    const fold = page.getByTestId('fold-strategies');
    await expect(fold).not.toHaveAttribute('open');
    await expect(fold.locator('.fold-body')).toHaveCount(0);
    await fold.locator('summary').click();
    await expect(page).toHaveURL(/[?&]open=strategies(&|$)/);
    const area = estimateOne(model, 'area', values.n, values.seed);
    await expect(page.getByTestId('estimate-area')).toHaveAttribute('data-value', String(area.estimate));
    await expect(page.getByTestId('estimate-cosine')).toHaveAttribute(
      'data-value',
      String(estimateOne(model, 'cosine', values.n, values.seed).estimate),
    );
  });
});

test('the floor images: they finish, follow the timeline, and the FLIP shown is that of the downloaded PNGs', async ({
  page,
}) => {
  test.setTimeout(120_000);
  // no animation: the timeline stands at its end, so the floor images show all 64 samples per pixel
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await openScene(page, '#/area-light?n=256&seed=4&strategy=area&open=floor');
  // a link opens the folds it names (here the floor images, beyond the exam)
  await expect(page.getByTestId('fold-floor')).toHaveAttribute('open', '');
  await test.step('at the end the running estimate is the n-sample estimate; the images finish', async () => {
    await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', '256');
    expect(await readout(page, 'anim-estimate')).toBe(await readout(page, 'estimate'));
    await page.locator('.al-images').scrollIntoViewIfNeeded();
    await expect(page.getByTestId('floor-spp')).toHaveAttribute('data-value', '64', { timeout: 30_000 });
    await expect(page.getByText(/64 samples per pixel \(done\)/)).toBeVisible();
    for (const s of ['area', 'solid-angle', 'cosine']) await readoutNumber(page, `image-rmse-${s}`);
  });

  await test.step('flip-mean equals the FLIP of the downloaded render and reference', async () => {
    await page.getByTestId('measure-details').locator('summary').click();
    await page.getByTestId('measure-image').selectOption('cosine');
    const shown = Number(await waitForReadout(page, 'flip-mean', (v) => v !== 'none' && v !== ''));
    await expect(page.getByTestId('measure-error-map')).toHaveAccessibleName(/FLIP error map, magma: mean/);
    const render = page.waitForEvent('download');
    await page.getByTestId('download-render').click();
    const r = await render;
    expect(r.suggestedFilename()).toMatch(/^area-light-floor-64spp-cosine-render\.png$/);
    const reference = page.waitForEvent('download');
    await page.getByTestId('download-reference').click();
    const ref = decodePng(await bytesOf(await reference));
    const img = decodePng(await bytesOf(r));
    expect([ref.width, ref.height]).toEqual([72, 72]);
    const mean = poolError(flipErrorMap(rgbFromRgba8(ref), rgbFromRgba8(img))).mean;
    expect(mean).toBeGreaterThan(0);
    expect(Math.abs(mean - shown)).toBeLessThanOrEqual(0.002);
  });

  await test.step('at sample 64 of 256 the images hold a quarter of their samples per pixel', async () => {
    await openScene(page, '#/area-light?n=256&seed=4&strategy=area&t=64&open=floor');
    await page.locator('.al-images').scrollIntoViewIfNeeded();
    await expect(page.getByTestId('floor-spp')).toHaveAttribute('data-value', '16', { timeout: 30_000 });
  });
});

test('work in workers: a large n without blocking (within 3σ), and the convergence and timing panels fill', async ({
  page,
}) => {
  test.setTimeout(180_000);
  await test.step('large n is estimated in a worker; the page answers meanwhile; the result is within 3σ', async () => {
    // above SYNC_MAX samples the estimates are computed in a worker, not on the main thread
    await openScene(page, `#/area-light?n=${2 * SYNC_MAX}&strategy=cosine&seed=5&open=sampling`);
    await waitForReadout(page, 'estimate', (v) => v !== 'none' && Number.isFinite(Number(v)), 30_000);
    // the page stays responsive meanwhile: a control reacts at once
    await expect(page.getByTestId('strategy')).toBeEnabled();
    const ref = await readoutNumber(page, 'reference');
    const est = await readoutNumber(page, 'estimate');
    const se = await readoutNumber(page, 'stderr');
    expect(se).toBeGreaterThan(0);
    expect(Math.abs(est - ref)).toBeLessThanOrEqual(3 * se);
  });

  // The "Convergence" and "Run time against error" panels (folds under Explore further) start their
  // worker runs when, once open, they come near the screen: their tables fill with one row per
  // checkpoint and one per (strategy, N), and their plots draw a line per strategy from the
  // scene's own code (no plotting library is fetched for them).
  await test.step('opened and scrolled into view, the convergence and timing panels get their data and draw it', async () => {
    const scripts: string[] = [];
    page.on('request', (r) => {
      if (r.resourceType() === 'script') scripts.push(new URL(r.url()).pathname);
    });
    await openScene(page, '#/area-light?open=convergence,timing');
    const convergence = page.getByTestId('al-convergence-table');
    await convergence.scrollIntoViewIfNeeded();
    await convergence.locator('summary').click();
    // checkpoints N = 2 … 32768: one row each, with |error| and σ for the three strategies
    const convRows = convergence.locator('tbody tr');
    await expect(convRows.first()).toBeVisible({ timeout: 45_000 });
    await expect(convRows.first().locator('td')).toHaveCount(1 + 2 * STRATEGIES.length);
    const timing = page.getByTestId('al-timing-table');
    await timing.scrollIntoViewIfNeeded();
    await timing.locator('summary').click();
    await expect(timing.locator('tbody tr')).toHaveCount(STRATEGIES.length * TIMING_COUNTS.length, {
      timeout: 90_000,
    });
    for (const id of ['al-convergence-plot', 'al-timing-plot']) {
      const plot = page.getByTestId(id);
      await plot.scrollIntoViewIfNeeded();
      // a marked line per strategy: its markers' path holds one shape per point
      await expect(plot.locator('svg.chart path.chart-markers')).toHaveCount(STRATEGIES.length, {
        timeout: 30_000,
      });
      expect(await plot.locator('svg.chart .chart-legend text').allTextContents()).toEqual(
        STRATEGIES.map((s) => STRATEGY_SHORT[s]),
      );
    }
    expect(scripts.filter((u) => /vendor-(?!three|katex)/.test(u))).toEqual([]);
  });
});
