/**
 * The teacher's guide (#/guide): a lazy chunk, axe clean, and every preset link opens its scene
 * with every parameter used (no notice, no error) and the scene computing.
 */
import AxeBuilder from '@axe-core/playwright';
import { LESSONS, presetHref } from '../../src/guide/lessons';
import { test, expect, openScene } from './fixtures';

test('the guide lists 3–5 presets per exam question, is reachable from the header, and is axe clean', async ({
  page,
}) => {
  test.setTimeout(240_000); // a full-page axe scan of a long page on a busy 2-core machine
  await openScene(page, '#/');
  await page.getByRole('link', { name: 'Teacher’s guide' }).click();
  await expect(page.getByRole('heading', { level: 1 })).toHaveText('Teacher’s guide');
  for (const q of ['Q1', 'Q2', 'Q3', 'Q4', 'Q5', 'Q6']) {
    const section = page.locator('section.guide-lesson', { has: page.locator('h2', { hasText: q }) });
    const n = await section.getByTestId('guide-preset').count();
    expect(n, q).toBeGreaterThanOrEqual(3);
    expect(n, q).toBeLessThanOrEqual(5);
  }
  await expect(page.getByRole('heading', { name: 'Misconceptions, scene by scene' })).toBeVisible();
  await expect(page.getByRole('heading', { name: 'Embed, print and go offline' })).toBeVisible();
  const results = await new AxeBuilder({ page }).analyze();
  const bad = results.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical');
  expect(
    bad.map(
      (v) =>
        `${v.id}: ${v.nodes
          .slice(0, 5)
          .map((n) => n.target.join(' '))
          .join(', ')}`,
    ),
  ).toEqual([]);
});

test('every preset link opens its scene with all its parameters used, on its part and in its state', async ({
  page,
}) => {
  test.setTimeout(400_000);
  await openScene(page, '#/guide?present=1');
  const hrefs = await page
    .locator('[data-testid="guide-preset"] h3 a')
    .evaluateAll((as) => as.map((a) => a.getAttribute('href')!));
  const presets = LESSONS.flatMap((l) => l.presets);
  expect(hrefs.length).toBeGreaterThanOrEqual(18);
  expect(hrefs).toEqual(presets.map((p) => presetHref(p, true)));
  for (const [i, href] of hrefs.entries()) {
    const p = presets[i];
    expect(href).toContain('present=1');
    // the link says what the preset's text says: its part, ask first, the animation's start
    const sp = new URLSearchParams(href.split('?')[1]);
    expect(sp.get('part'), href).toBe(p.part ?? null);
    expect(sp.get('ask'), href).toBe(p.askFirst ? '1' : null);
    await openScene(page, href);
    await expect(page.locator('main#main.scene')).toBeVisible();
    await expect(page.getByTestId('param-notice'), href).toHaveCount(0);
    await expect(page.locator('.notice-error'), href).toHaveCount(0);
    await expect(page.getByTestId('copy-link')).toBeVisible();
    // asking, it lands with its own question on the screen (the room predicts first); showing
    // everything at once, it lands on its part (scrolled to and focused)
    if (p.askFirst) {
      await expect(page.getByTestId('ask-prompt-text'), href).toHaveText(p.ask);
      await expect(page.getByTestId('ask-prompt-text'), href).toBeInViewport();
    } else {
      await expect(page.getByTestId('ask-prompt'), href).toHaveCount(0);
      if (p.part) await expect(page.locator(`#part-${p.part}`), href).toBeFocused();
    }
    // … and holds its animation where the link says (or, asking, hides its transport until revealed;
    // what a scene does on Reveal, e.g. play what was predicted, is the scene's own test)
    if (p.params.t !== undefined) {
      const timeline = page.locator('.timeline');
      if (p.askFirst && (await timeline.count()) === 0)
        await expect(page.getByTestId('ask-hidden').first(), href).toBeVisible();
      else await expect(timeline.first(), href).toHaveAttribute('data-t', p.params.t);
    }
  }
});
