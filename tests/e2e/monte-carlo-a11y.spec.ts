/**
 * #/monte-carlo for a reader who cannot see it, read from Chromium's accessibility tree (CDP): the
 * race's description holds the live numbers and follows a parameter and the paused position, the
 * audio traces start Web Audio nodes and step by key, ask=1 hides the results until Reveal,
 * classroom mode keeps the race on the first screen, and a keyboard-only run reads Q4's answers
 * from the tree. Expected numbers come from the model (raceTrack / raceAt) or from the formula.
 */
import type { Page } from '@playwright/test';
import { test, expect, openScene } from './fixtures';
import { axNodeOf, axTree } from './axTree';
import { raceAt, raceTrack } from '../../src/scenes/monte-carlo/race';
import { squarePdf1D } from '../../src/core/sampling/pdf1d';

test.describe.configure({ timeout: 120_000 });

const f = (x: number) => (x + 2) ** 2;
const I = (4 ** 3 - 2 ** 3) / 3;
const EXAM_X = [1.16, 1.98, 0.54, 1.26];
const examTrack = (seed: number) => raceTrack(f, 0, 2, squarePdf1D(0, 2, 2), I, seed);
const RACE = '[data-testid="race-figure"]';

const description = async (page: Page, sel = RACE) => (await axNodeOf(page, sel))?.description ?? '';

/** The uniform lane's "estimate ± error" as the description writes it, checked against the model. */
function expectUniform(desc: string, t: number, seed: number) {
  const fr = raceAt(examTrack(seed), t, []);
  const m = /uniform estimate (\d+\.?\d*) ± (\d+\.?\d*)/.exec(desc);
  expect(m, desc).not.toBeNull();
  const [est, se] = [Number(m![1]), Number(m![2])];
  // written to the error's first digit (two from a leading 1): within half a unit of that digit
  const e = Math.floor(Math.log10(fr.uniform.stderr));
  const unit = 10 ** (fr.uniform.stderr / 10 ** e < 2 ? e - 1 : e);
  expect(Math.abs(est - fr.uniform.estimate)).toBeLessThanOrEqual(unit / 2 + 1e-12);
  expect(Math.abs(se - fr.uniform.stderr)).toBeLessThanOrEqual(unit / 2 + 1e-12);
}

test('the race’s description: live numbers at the opening position, then after a parameter change', async ({
  page,
}) => {
  await openScene(page, '#/monte-carlo');
  const node = await axNodeOf(page, RACE);
  expect(node!.role).toBe('group');
  expect(node!.name).toMatch(/uniform against importance sampling/);
  const t = Number(await page.getByTestId('timeline').getAttribute('data-t'));
  const desc = node!.description;
  expect(desc.startsWith(`${t.toLocaleString('en')} samples: uniform estimate`)).toBe(true);
  expectUniform(desc, t, 1);
  expect(desc).toContain(`importance (p ∝ f) ${I.toPrecision(4)} ± 0 (zero variance)`);
  expect(desc).toContain(`exact I = ${Number(I.toPrecision(6))}`);
  // where the samples fell, as the model's samples say
  const tr = examTrack(1);
  const share = (xs: Float64Array) =>
    Math.round((100 * Array.from(xs.subarray(0, t)).filter((x) => x >= 1 && x <= 2).length) / t);
  expect(desc).toContain(`${share(tr.importance.x)} % of the importance samples lie in [1, 2]`);
  expect(desc).toContain(`against ${share(tr.uniform.x)} % of the uniform ones`);
  // the inner plots are named and described too
  expect((await axNodeOf(page, '[data-testid="race-errors"]'))!.description).toMatch(/falls as N⁻/);
  expect((await axNodeOf(page, '[data-testid="race-histogram-importance"]'))!.description).toContain(
    `Histogram of all ${t.toLocaleString('en')} importance samples`,
  );

  // a parameter: another seed gives another description, with that seed's numbers
  const seed = page.getByTestId('seed-input');
  await seed.fill('7');
  await seed.press('Enter');
  await expect.poll(() => description(page), { timeout: 15_000 }).not.toBe(desc);
  expectUniform(await description(page), t, 7);
  // and it is announced once settled
  await expect(page.getByTestId('live-region')).toHaveText(await description(page), { timeout: 15_000 });
});

test('the description follows the animation: said again on pause with the paused position', async ({
  page,
}) => {
  await openScene(page, '#/monte-carlo?seed=4');
  const tl = page.getByTestId('timeline');
  const before = await description(page);
  const play = page.getByTestId('timeline-play');
  await play.focus();
  await page.keyboard.press('Enter');
  await expect(tl).toHaveAttribute('data-playing', '1');
  await expect
    .poll(async () => Number(await tl.getAttribute('data-t')), { timeout: 20_000 })
    .toBeGreaterThan(1100);
  await page.keyboard.press('Enter');
  await expect(tl).toHaveAttribute('data-playing', '0');
  const t = Number(await tl.getAttribute('data-t'));
  await expect.poll(() => description(page)).toMatch(new RegExp(`^${t.toLocaleString('en')} samples:`));
  const after = await description(page);
  expect(after).not.toBe(before);
  expectUniform(after, t, 4);
  await expect(page.getByTestId('live-region')).toHaveText(after, { timeout: 15_000 });
});

test('the audio traces: nothing sounds until asked, arrows step and speak, Enter plays Web Audio', async ({
  page,
}) => {
  await page.addInitScript(() => {
    const w = window as unknown as { __osc: number };
    w.__osc = 0;
    const orig = AudioContext.prototype.createOscillator;
    AudioContext.prototype.createOscillator = function (this: AudioContext) {
      w.__osc++;
      return orig.call(this);
    };
  });
  await openScene(page, '#/monte-carlo?t=2000');
  const count = () => page.evaluate(() => (window as unknown as { __osc: number }).__osc);
  const live = page.getByTestId('live-region');
  const fr = raceAt(examTrack(1), 2000);
  const trace = page.getByTestId('trace-uniform-estimate');
  await trace.focus();
  await page.keyboard.press('ArrowRight');
  await expect(live).toHaveText(
    new RegExp(
      `^log₁₀ N = 0, uniform estimate = ${fr.curve.u[0].toPrecision(3)} .*\\(point 1 of ${fr.curve.n.length}\\)`,
    ),
  );
  await page.keyboard.press('End');
  await expect(live).toHaveText(new RegExp(`uniform estimate = ${fr.uniform.estimate.toPrecision(3)}`));
  expect(await count()).toBe(0);
  await page.keyboard.press('Enter');
  await expect(live).toHaveText(/^Playing uniform running estimate/);
  // one tone, and a tick where the estimate crosses the exact I
  await expect.poll(count, { timeout: 15_000 }).toBeGreaterThan(1);
  await page.keyboard.press('Escape');
  await expect(live).toHaveText('Stopped.');
  // the |error| trace reads log–log values
  await page.getByTestId('trace-uniform-error').focus();
  await page.keyboard.press('End');
  await expect(live).toHaveText(
    new RegExp(`log₁₀ \\|error\\| = ${Math.log10(fr.uniform.absError).toPrecision(3).replace('-', '−')}`),
  );
  // the p ∝ f lane has zero variance: no trace of rounding noise
  await expect(page.getByTestId('trace-importance-error')).toHaveCount(0);
});

test('the histograms and the race’s curves as tables: the counts of all samples drawn', async ({ page }) => {
  await openScene(page, '#/monte-carlo?t=600');
  const t = page.getByTestId('race-hist-table-importance');
  await t.locator('summary').click();
  // the rows render once the table is opened: one per bin of width 1/12 on [0, 2]
  await expect(t.locator('tbody tr')).toHaveCount(24);
  const counts = (await t.locator('tbody tr td:nth-child(3)').allTextContents()).map(Number);
  expect(counts.reduce((s, c) => s + c, 0)).toBe(600);
  const xs = examTrack(1).importance.x.subarray(0, 600);
  expect(counts).toEqual(
    counts.map((_, k) => Array.from(xs).filter((x) => Math.min(23, Math.floor(x * 12)) === k).length),
  );
  const race = page.getByTestId('race-table');
  await race.locator('summary').click();
  await expect(race.locator('th[scope="col"]').first()).toHaveText('N');
  await expect(race.locator('tbody tr').last().locator('td').first()).toHaveText('600');
  expect((await axTree(page)).filter((n) => n.role === 'table').length).toBeGreaterThanOrEqual(2);
});

test('ask=1: the answers and the race’s samples are hidden and it holds at t = 0; Reveal shows them', async ({
  page,
}) => {
  await openScene(page, '#/monte-carlo?ask=1');
  await expect(page.getByTestId('ask-prompt')).toBeVisible();
  expect(await page.getByTestId('ask-hidden').count()).toBeGreaterThan(2);
  await expect(page.getByTestId('q4-answer-a')).toHaveCount(0);
  await expect(page.getByTestId('q4-uniform')).toHaveCount(0);
  await expect(page.getByTestId('timeline')).toHaveCount(0);
  await expect.poll(() => page.evaluate(() => location.hash)).toMatch(/[?&]t=0(&|$)/);
  const held = await description(page);
  expect(held).toMatch(/^No samples drawn yet/);
  expect(held).not.toContain(I.toPrecision(4));
  // nothing that gives the integral away: no estimate or |error| axes while held
  await expect(page.getByTestId('race-estimate-uniform')).toHaveCount(0);
  await expect(page.getByTestId('race-errors')).toHaveCount(0);
  // the setup stays: f and the pdfs over the empty histograms
  await expect(page.getByTestId('race-hist-uniform')).toHaveAttribute('data-t', '0');
  await page.getByTestId('reveal').click();
  await expect(page.getByTestId('ask-hidden')).toHaveCount(0);
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-t', '0');
  await expect(page.getByTestId('q4-answer-a')).toHaveAttribute('data-value', String(I));
  await expect(page.getByTestId('race-errors')).toHaveCount(1);
  expect(await description(page)).toMatch(/^No samples drawn yet .*play or step/);
});

// the projector's common size (the stage's general checks run for every scene in catalogue.spec.ts)
for (const [width, height] of [[1280, 720]] as const) {
  test(`present=1 at ${width}×${height}: the race’s transport, readouts and histograms are on the first screen`, async ({
    page,
  }) => {
    await page.setViewportSize({ width, height });
    await openScene(page, '#/monte-carlo?present=1');
    await page.evaluate(() => scrollTo(0, 0));
    const stage = page.getByTestId('scene-stage');
    await expect(stage.getByTestId('race-figure')).toBeVisible();
    for (const id of [
      'timeline',
      'race-uniform-estimate',
      'race-importance-stderr',
      'race-hist-uniform',
      'race-hist-importance',
    ]) {
      const box = (await stage.getByTestId(id).boundingBox())!;
      expect(box.y + box.height, id).toBeLessThanOrEqual(height);
      expect(box.x + box.width, id).toBeLessThanOrEqual(width);
    }
    // the answers follow on the page below the stage
    await expect(page.getByTestId('q4-answers')).toHaveCount(1);
  });
}

test('keyboard only: back to the exam’s configuration, Q4’s answers read from the accessibility tree', async ({
  page,
}) => {
  await openScene(page, '#/monte-carlo?f=x%5E2');
  // Tab to the "Exam configuration" button and press it
  let found = false;
  for (let i = 0; i < 80 && !found; i++) {
    await page.keyboard.press('Tab');
    found = await page.evaluate(() => document.activeElement?.textContent === 'Exam configuration');
  }
  expect(found).toBe(true);
  await page.keyboard.press('Enter');
  await expect(page.getByTestId('not-exam-config')).toHaveCount(0);
  // the numbers the exam asks for, as a screen reader gets them
  const uni = (2 / 4) * EXAM_X.reduce((s, x) => s + f(x), 0);
  await expect
    .poll(async () => (await axTree(page)).map((n) => n.name).join('\n'), { timeout: 15_000 })
    .toContain(`= ${Math.round(3 * I)}/3`);
  const names = (await axTree(page)).map((n) => n.name);
  expect(names).toContain(I.toPrecision(6));
  expect(names).toContain(uni.toPrecision(6));
  expect(names).toContain(`≈ ${uni.toFixed(2)} to 2 decimals`);
  expect(names.some((n) => /every term f\/p is the same \(zero variance\)/.test(n))).toBe(true);
  // (d): play the race from the keyboard and read the paused state from the figure's description
  let play = false;
  for (let i = 0; i < 40 && !play; i++) {
    await page.keyboard.press('Tab');
    play = await page.evaluate(() => document.activeElement?.getAttribute('data-testid') === 'timeline-play');
  }
  expect(play).toBe(true);
  await page.keyboard.press('Enter');
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '1');
  await page.keyboard.press('Enter');
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
  await expect.poll(() => description(page)).toMatch(/importance \(p ∝ f\) 18\.67 ± 0 \(zero variance\)/);
});
