/**
 * The teacher's guide (#/guide) in the browser: reached from the site header, its preset links
 * are the lessons' own, and a preset lands where its text says: asking, with its own question on
 * the screen; showing everything, on its part (scrolled to and focused); with its animation held
 * where the link says. That every preset's parameters are all used (no notice) is checked for
 * every preset in Node (tests/guide/lessons.test.ts), and the page's axe and WCAG pass is
 * wcag.spec.ts's.
 */
import { LESSONS, presetHref, type Preset } from '../../src/guide/lessons';
import { test, expect, openScene } from './fixtures';

test('reached from the header, the guide links every preset; a preset lands asking, on its part, and at its t', async ({
  page,
}) => {
  test.setTimeout(180_000);
  await openScene(page, '#/');
  await page.getByRole('link', { name: 'Teacher’s guide' }).click();
  await expect(page.getByRole('heading', { level: 1 })).toHaveText('Teacher’s guide');
  await expect(page.getByRole('heading', { name: 'Misconceptions, scene by scene' })).toBeVisible();
  await expect(page.getByRole('heading', { name: 'Embed, print and go offline' })).toBeVisible();
  await openScene(page, '#/guide?present=1');
  const hrefs = await page
    .locator('[data-testid="guide-preset"] h3 a')
    .evaluateAll((as) => as.map((a) => a.getAttribute('href')!));
  const presets = LESSONS.flatMap((l) => l.presets);
  expect(hrefs).toEqual(presets.map((p) => presetHref(p, true)));

  // one of each way to land: asking first; on a part; at a position of the animation
  const chosen = [
    presets.find((p) => p.askFirst),
    presets.find((p) => !p.askFirst && p.part),
    presets.find((p) => p.params.t !== undefined),
  ].filter((p): p is Preset => p !== undefined);
  expect(chosen).toHaveLength(3);
  for (const p of chosen) {
    const href = presetHref(p, true);
    await page.locator(`[data-testid="guide-preset"] h3 a[href="${href}"]`).click();
    await expect(page.locator('main#main.scene')).toBeVisible();
    await expect(page.getByTestId('param-notice'), href).toHaveCount(0);
    await expect(page.locator('.notice-error'), href).toHaveCount(0);
    if (p.askFirst) {
      await expect(page.getByTestId('ask-prompt-text'), href).toHaveText(p.ask);
      await expect(page.getByTestId('ask-prompt-text'), href).toBeInViewport();
    } else {
      await expect(page.getByTestId('ask-prompt'), href).toHaveCount(0);
      if (p.part) await expect(page.locator(`#part-${p.part}`), href).toBeFocused();
    }
    if (p.params.t !== undefined) {
      const timeline = page.locator('.timeline');
      if (p.askFirst && (await timeline.count()) === 0)
        await expect(page.getByTestId('ask-hidden').first(), href).toBeVisible();
      else await expect(timeline.first(), href).toHaveAttribute('data-t', p.params.t);
    }
    await page.goBack();
    await expect(page.getByRole('heading', { level: 1 })).toHaveText('Teacher’s guide');
  }
});
