/**
 * The lecture room (present=1 on a 1280×720 projector): Q4's convergence graph on the stage with
 * data; a Q4(d) lesson preset asks its question on screen, reveals (`v`) and plays (Space) the race
 * in view, its histograms counting the samples drawn; `r` goes back to the state the page was
 * opened with; Copy link and the QR code keep classroom mode and the held-back results, and
 * nothing of the page's own query; a lesson preset chosen in the guide opens with its question in
 * view; every plot's tick labels are at least 18 px. The link's flags themselves are unit-tested (tests/kit/shareLink.test.ts).
 */
import type { Page } from '@playwright/test';
import { LESSON_PRESETS } from '../../src/kit/lessons';
import { expect, openScene, settle, test } from './fixtures';

const PROJECTOR = { width: 1280, height: 720 };

/** The lesson preset of question `q` titled `title` (its question to the class). */
function preset(q: 3 | 4, title: string) {
  const p = LESSON_PRESETS[q].find((x) => x.title === title);
  if (!p) throw new Error(`no Q${q} preset titled ${title}`);
  return p;
}

/** Points of the polylines in a figure's paths matching `sel` (their move and line commands). */
async function plotted(page: Page, testId: string, sel: string): Promise<number> {
  return page
    .getByTestId(testId)
    .locator(sel)
    .evaluateAll((ps) =>
      ps.reduce((n, p) => n + ((p.getAttribute('d') ?? '').match(/[ML]/g)?.length ?? 0), 0),
    );
}

const position = (page: Page) => page.getByTestId('timeline').getAttribute('data-t').then(Number);

test('Q4 at 1280×720: the convergence graph on the stage; a 4d preset reveals and plays in view; r opens the page again; the plots’ tick labels are 18 px or more', async ({
  page,
}) => {
  test.setTimeout(180_000);
  await page.setViewportSize(PROJECTOR);
  await openScene(page, '#/monte-carlo?present=1');
  const stage = page.getByTestId('scene-stage');
  // ⟨I⟩ against N with its ± s/√N band (both lanes) and |error| against N: on the first screen, drawn
  for (const id of ['race-estimate-uniform', 'race-estimate-importance', 'race-errors']) {
    await expect(stage.getByTestId(id), id).toBeInViewport({ ratio: 1 });
  }
  expect(await plotted(page, 'race-estimate-uniform', 'path.rep-line')).toBeGreaterThan(10);
  expect(await plotted(page, 'race-estimate-uniform', 'path.rep-band')).toBeGreaterThan(10);
  expect(await plotted(page, 'race-errors', 'path.mc-svg-line')).toBeGreaterThan(10);

  // r with focus in the transport, while playing: the opening state (t = 1024), not the start
  await page.getByTestId('timeline-play').click();
  await expect.poll(() => position(page)).toBeGreaterThan(1100);
  await page.keyboard.press('r');
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-t', '1024');
  expect(await page.evaluate(() => location.hash)).toBe('#/monte-carlo?present=1');

  // the lecturer opens a Q4(d) preset: its question and the held race on screen
  const ramp = preset(4, 'A pdf that is close to f');
  await page.evaluate(() => {
    location.hash = '#/monte-carlo?pdf=linear&t=0&part=4d&ask=1&present=1';
  });
  await expect(page.getByTestId('ask-prompt-text')).toHaveText(ramp.ask);
  await expect(page.getByTestId('ask-prompt-text')).toBeInViewport();
  await expect(stage).toBeInViewport();
  // v reveals the race where it is, not the text answer further down
  await page.keyboard.press('v');
  await expect(page.getByTestId('ask-prompt')).toHaveCount(0);
  await expect(stage.getByTestId('timeline')).toBeInViewport({ ratio: 1 });
  await expect(stage.getByTestId('race-estimate-uniform')).toBeInViewport({ ratio: 1 });
  await expect(page.getByTestId('answer-4d')).not.toBeInViewport();
  // Space plays the race in view; the histograms' captions count the samples drawn while it plays
  await page.keyboard.press('Space');
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '1');
  const caption = page.getByTestId('race-hist-caption-importance');
  await expect.poll(async () => Number((await caption.textContent())?.match(/\d+/)?.[0])).toBeGreaterThan(0);
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '1');
  await page.keyboard.press('Space');
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
  const t = await position(page);
  expect(t).toBeGreaterThan(0);
  await expect(caption).toHaveText(`All ${t} samples against p(x)`);
  await expect(page.getByTestId('race-hist-caption-uniform')).toHaveText(`All ${t} samples against p(x)`);

  // r: the page's opening state (uniform pdf, t = 1024), not the preset's
  await page.keyboard.press('r');
  await expect(page.getByTestId('timeline')).toHaveAttribute('data-t', '1024');
  expect(await page.evaluate(() => location.hash)).not.toMatch(/pdf=|[?&]t=/);
  await expect(stage.getByRole('heading', { name: /^Importance, p ∝ f/ })).toBeVisible();

  await test.step('every plot’s tick labels are at least 18 px', async () => {
    // every plot of the page: those of Explore further are folded, the link opens them
    await openScene(page, '#/monte-carlo?present=1&open=integrand,convergence,rmse,unbiased');
    const height = await page.evaluate(() => document.documentElement.scrollHeight);
    for (let y = 0; y < height; y += 600) {
      await page.evaluate((y) => window.scrollTo(0, y), y);
      await settle(page);
    }
    await expect(page.locator('svg.chart .chart-xticks text').first()).toBeAttached({ timeout: 60_000 });
    const sizes = await page
      .locator('svg.chart :is(.chart-xticks, .chart-yticks, .chart-colorbar) text')
      .evaluateAll((ts) =>
        ts.map((t) => ({
          px: parseFloat(getComputedStyle(t).fontSize),
          what: `${t.closest('figure')?.getAttribute('aria-label')?.slice(0, 40)}: ${t.textContent}`,
        })),
      );
    expect(sizes.length).toBeGreaterThan(0);
    expect(sizes.filter((s) => s.px < 17.5).map((s) => `${s.what} at ${s.px} px`)).toEqual([]);
  });
});

test('present=1: Copy link and the QR code keep present=1 and ask=1, and none of the page’s own query; a lesson preset chosen in the guide opens with its question in view', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await page.setViewportSize(PROJECTOR);
  await test.step('Copy link and the QR code keep present=1 and ask=1, and none of the page’s own query', async () => {
    await page.goto('./?userid=1&email=a%40b#/texture?present=1&ask=1');
    await expect(page.getByTestId('ask-prompt')).toBeVisible();
    // the link is the room as it stands: no choice to make
    await expect(page.getByTestId('keep-classroom')).toHaveCount(0);
    await page.getByTestId('copy-link').click();
    await expect(page.locator('.share-status')).toHaveText('Link copied.');
    const copied = await page.evaluate(() => navigator.clipboard.readText());
    expect(copied).toMatch(/\/app\/#\/texture\?/);
    expect(copied).toMatch(/[?&]present=1(&|$)/);
    expect(copied).toMatch(/[?&]ask=1(&|$)/);
    expect(copied).not.toMatch(/userid|email|a%40b|a@b/);
    await page.getByTestId('show-qr').click();
    await expect(page.getByTestId('qr-code')).toHaveAttribute('data-text', copied);
    await expect(page.getByTestId('qr-panel')).toContainText('in classroom mode');
    await expect(page.getByTestId('qr-keep-classroom')).toHaveCount(0);
  });

  await test.step('a lesson preset chosen in the guide opens with its question in view, on two scenes', async () => {
    for (const [q, title, route] of [
      [4, 'A pdf that is close to f', '#/monte-carlo?'],
      [3, 'The exam’s lookup (Q3a, Q3b)', '#/texture?'],
    ] as const) {
      // (by the hash: the page's own query stays, and the app is not loaded again)
      await page.evaluate(() => (location.hash = '#/guide?present=1'));
      await expect(page.getByRole('link', { name: title, exact: true })).toBeVisible();
      await page.getByRole('link', { name: title, exact: true }).click();
      await expect(page).toHaveURL(new RegExp(`${route.replace(/[?]/g, '\\?')}.*part=.*ask=1.*present=1`));
      await expect(page.locator('.loading')).toHaveCount(0);
      // the page has drawn its parts (the part the link names among them) and stays on the question
      await expect(page.locator('[data-deferred="pending"]')).toHaveCount(0, { timeout: 30_000 });
      const text = page.getByTestId('ask-prompt-text');
      await expect(text, title).toHaveText(preset(q, title).ask);
      await expect(text, title).toBeInViewport({ ratio: 1 });
      await expect(page.getByTestId('scene-stage'), title).toBeInViewport();
    }
  });
});
