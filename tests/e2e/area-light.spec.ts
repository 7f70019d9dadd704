/**
 * Browser tests of #/area-light: the readouts are the scene's model (computed here in Node from the
 * same query), bad input gives a message and a fallback, the exam's parts come first, and the
 * animation's readouts follow the timeline; what is beyond the exam is folded until opened. The
 * estimators' and the solid angle's numbers are unit
 * tests (tests/scenes/area-light/cases.test.ts, tests/core/lights/).
 */
import { test, expect, openScene, readout, readoutNumber } from './fixtures';
import { defaultValues, parseParams } from '../../src/kit/params';
import { schema } from '../../src/scenes/area-light/params';
import { animationFrame, animationLength, sampleRun } from '../../src/scenes/area-light/animation';
import { buildModel, estimateOne, givenSamples } from '../../src/scenes/area-light/model';
import { patchModel } from '../../src/scenes/area-light/patch';
import type { LightStrategy } from '../../src/core/lights';

/** The model computed here, in Node, from a query string (the same parser as the app). */
function modelFor(query: string) {
  const values = { ...defaultValues(schema), ...parseParams(schema, new URLSearchParams(query)).values };
  return { values, model: buildModel(values) };
}

test('wiring: the readouts are the model’s for the exam’s light, an off-axis light and an occluded one', async ({
  page,
}) => {
  // the placements' numbers themselves (Ω against the corner formula, every strategy within 3σ)
  // are unit tests: tests/scenes/area-light/cases.test.ts
  for (const q of [
    '',
    'p=0.2,-0.4,0&lc=0.9,0.3,1.5&ls=1.2,0.8&tilt=0&strategy=solid-angle&n=4096&seed=7',
    'occluder=1&strategy=cosine&n=4096&seed=3',
  ]) {
    await openScene(page, `#/area-light${q ? `?${q}` : ''}`);
    const { values, model } = modelFor(q);
    expect(await readoutNumber(page, 'reference'), q).toBe(model.reference);
    expect(await readoutNumber(page, 'solid-angle'), q).toBe(model.solidAngle);
    const want = estimateOne(model, values.strategy as LightStrategy, values.n, values.seed);
    expect(await readoutNumber(page, 'estimate'), q).toBe(want.estimate);
    expect(await readoutNumber(page, 'stderr'), q).toBe(want.stderr);
    if (model.referenceOccluded === null) expect(await readout(page, 'reference-occluded'), q).toBe('none');
    else expect(await readoutNumber(page, 'reference-occluded'), q).toBe(model.referenceOccluded);
  }
});

test('changing the strategy updates the URL and the estimate; the floor images finish', async ({ page }) => {
  // the strategy (fold "sampling") and the floor images (fold "floor") are one click away: opened by the link
  await openScene(page, '#/area-light?n=2048&open=sampling,floor');
  const before = await readout(page, 'estimate');
  await page.getByTestId('strategy').selectOption('cosine');
  await expect(page).toHaveURL(/strategy=cosine/);
  await expect(page.getByTestId('estimate')).not.toHaveAttribute('data-value', before);
  await page.locator('.al-images').scrollIntoViewIfNeeded();
  await expect(page.getByText(/64 samples per pixel \(done\)/)).toBeVisible({ timeout: 30000 });
  for (const s of ['area', 'solid-angle', 'cosine']) await readoutNumber(page, `image-rmse-${s}`);
});

test('large n is estimated in a worker without blocking; the result agrees within 3σ', async ({ page }) => {
  await openScene(page, '#/area-light?n=300000&strategy=cosine&seed=5&open=sampling');
  const { waitForReadout } = await import('./fixtures');
  await waitForReadout(page, 'estimate', (v) => v !== 'none' && Number.isFinite(Number(v)), 30000);
  // the page stays responsive meanwhile: a control reacts at once
  await expect(page.getByTestId('strategy')).toBeEnabled();
  const ref = await readoutNumber(page, 'reference');
  const est = await readoutNumber(page, 'estimate');
  const se = await readoutNumber(page, 'stderr');
  expect(se).toBeGreaterThan(0);
  expect(Math.abs(est - ref)).toBeLessThanOrEqual(3 * se);
});

// ------------------------------------------------------------------------------------------------
// Exam first and the animation.

test('exam first: 6a, 6b, 6c in order before "Explore further", each with its derivation and live numbers', async ({
  page,
}) => {
  const q = 'psize=0.3&ptilt=40&seed=9&occluder=1';
  await openScene(page, `#/area-light?${q}`);
  const ids = ['part-6a', 'part-6b', 'part-6c', 'explore-further'];
  const tops: number[] = [];
  for (const id of ids) {
    const el = id === 'explore-further' ? page.getByTestId(id) : page.locator(`#${id}`);
    await expect(el).toBeVisible();
    tops.push((await el.boundingBox())!.y);
  }
  expect([...tops].sort((a, b) => a - b)).toEqual(tops);
  const { values, model } = modelFor(q);
  const patch = patchModel(model, values.pu, values.pv, values.psize, values.ptilt);
  // 6a: the similar-triangles steps, with dl, dω_l and the result for this patch
  const d6a = page.getByTestId('derivation-6a');
  await expect(d6a).toContainText('similar triangles');
  const dl = Math.sqrt(patch.area * patch.cosThetaL);
  await expect(page.getByTestId('step-6a-perp')).toContainText(`dl = ${Number(dl.toPrecision(4))}`);
  // dωₗ is written with a real subscript (dω<sub>l</sub>): its text is "dωl"
  await expect(page.getByTestId('step-6a-similar')).toContainText(
    `dωl = ${Number((dl / patch.r).toPrecision(4))}`,
  );
  await expect(page.getByTestId('step-6a-result')).toContainText(String(Number(patch.approx.toPrecision(6))));
  expect(await readoutNumber(page, 'patch-approx')).toBeCloseTo(patch.approx, 7);
  // 6b: the four steps (Jacobian J_T, then V, then cos θ_l / r²) with the Jacobian's value
  await expect(page.getByTestId('derivation-6b').locator('.katex')).toHaveCount(4);
  await expect(page.getByTestId('step-6b-jacobian')).toContainText(
    String(Number((patch.cosThetaL / patch.r ** 2).toPrecision(4))),
  );
  // 6c: p_A = 1/|A| and the four given samples' terms, their mean as the N = 4 estimate
  await expect(page.getByTestId('step-6c-pdf')).toContainText(
    `|A| = ${Number(model.light.area.toPrecision(4))}`,
  );
  const g = givenSamples(model, values.seed, 4);
  for (let i = 0; i < 4; i++) {
    const v = Number(await page.getByTestId(`given-term-${i + 1}`).getAttribute('data-value'));
    expect(v).toBeCloseTo(g.samples[i].term, 12);
  }
  expect(await readoutNumber(page, 'given-estimate')).toBeCloseTo(g.estimate, 6);

  // beyond the exam, folded: the strategies' table is closed with nothing in it until clicked; it
  // then computes the three estimates, and the link remembers it open
  const fold = page.getByTestId('fold-strategies');
  await expect(fold).not.toHaveAttribute('open');
  await expect(fold.locator('.fold-body')).toHaveCount(0);
  await fold.locator('summary').click();
  await expect(page).toHaveURL(/[?&]open=strategies(&|$)/);
  const area = estimateOne(model, 'area', values.n, values.seed);
  await expect(page.getByTestId('estimate-area')).toHaveAttribute('data-value', String(area.estimate));
  await page.reload();
  await expect(page.getByTestId('fold-strategies')).toHaveAttribute('open');
  await expect(page.getByTestId('estimate-cosine')).toHaveAttribute(
    'data-value',
    String(estimateOne(model, 'cosine', values.n, values.seed).estimate),
  );
});

/** Readouts of the animation at position t, computed here. */
function animAt(query: string, t: number) {
  const { values, model } = modelFor(query);
  const run = sampleRun(model, values.strategy as LightStrategy, animationLength(values.n), values.seed);
  return animationFrame(run, t);
}

test('animation: play, pause, and the readouts equal the model at the paused position; a link restores them; step adds one', async ({
  page,
}) => {
  const q = 'strategy=solid-angle&n=512&seed=21&t=0';
  await openScene(page, `#/area-light?${q}`);
  await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', '0');
  const tl = page.getByTestId('timeline');
  await tl.getByRole('button', { name: /play/i }).click();
  await expect
    .poll(async () => Number(await page.getByTestId('anim-k').getAttribute('data-value')), { timeout: 20000 })
    .toBeGreaterThan(20);
  await tl.getByRole('button', { name: /pause/i }).click();
  await expect(tl).toHaveAttribute('data-playing', '0');
  await expect(page).toHaveURL(/[?&]t=\d+/);
  const t = Number(/[?&]t=(\d+)/.exec(page.url())![1]);
  const k = Number(await page.getByTestId('anim-k').getAttribute('data-value'));
  expect(k).toBe(t);
  const want = animAt(q.replace('t=0', `t=${t}`), t);
  expect(await readoutNumber(page, 'anim-estimate')).toBeCloseTo(want.estimate, 6);
  expect(await readoutNumber(page, 'anim-stderr')).toBeCloseTo(want.stderr, 2);
  // the link with t and the seed reopens exactly there
  const url = page.url();
  const est = await readout(page, 'anim-estimate');
  await page.goto('about:blank');
  await openScene(page, url.slice(url.indexOf('#')));
  await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', String(t));
  expect(await readout(page, 'anim-estimate')).toBe(est);
  // step: one more sample
  await tl.getByRole('button', { name: /step/i }).click();
  await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', String(t + 1));
  expect(await readoutNumber(page, 'anim-estimate')).toBeCloseTo(animAt(q, t + 1).estimate, 6);
});

test('animation: at the end the running estimate is the n-sample estimate; the floor images follow the timeline', async ({
  page,
}) => {
  await openScene(page, '#/area-light?n=256&seed=4&strategy=area&open=floor');
  await expect(page.getByTestId('anim-k')).toHaveAttribute('data-value', '256');
  expect(await readout(page, 'anim-estimate')).toBe(await readout(page, 'estimate'));
  await page.locator('.al-images').scrollIntoViewIfNeeded();
  await expect(page.getByText(/64 samples per pixel \(done\)/)).toBeVisible({ timeout: 30000 });
  await openScene(page, '#/area-light?n=256&seed=4&strategy=area&t=64&open=floor');
  await page.locator('.al-images').scrollIntoViewIfNeeded();
  await expect(page.getByTestId('floor-spp')).toHaveAttribute('data-value', '16', { timeout: 30000 });
});
