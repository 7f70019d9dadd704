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
  // the histograms and the seed field are folded: the link opens them
  await openScene(page, '#/monte-carlo?open=race-histograms,settings');
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
