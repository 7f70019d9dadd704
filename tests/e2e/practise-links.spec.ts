/**
 * "Practise this": every exam part of every scene links to its question's practice page (a fixed
 * variant and a fresh one), and together the scenes reach all six questions.
 */
import { test, expect, openScene } from './fixtures';

const ROUTES = ['hemisphere', 'monte-carlo', 'texture', 'ray-sphere', 'area-light'];

test('every scene’s exam parts link to their practice question', async ({ page }) => {
  test.setTimeout(180_000);
  const reached = new Set<string>();
  for (const route of ROUTES) {
    await openScene(page, `#/${route}`);
    const parts = page.locator('section.exam-part');
    const n = await parts.count();
    expect(n, route).toBeGreaterThan(0);
    for (let i = 0; i < n; i++) {
      const id = (await parts.nth(i).getAttribute('id'))!.replace(/^part-/, '');
      const q = id[0];
      await expect(parts.nth(i).getByTestId(`practise-link-${id}`)).toHaveAttribute(
        'href',
        new RegExp(`^#/practice/q${q}\\?seed=\\d+$`),
      );
      await expect(parts.nth(i).getByTestId(`practise-fresh-${id}`)).toHaveAttribute(
        'href',
        `#/practice/q${q}`,
      );
      reached.add(q);
    }
  }
  expect([...reached].sort()).toEqual(['1', '2', '3', '4', '5', '6']);
  // following the links opens the practice page: the fixed variant, and a fresh one with its seed named
  await openScene(page, '#/texture');
  await page.getByTestId('practise-link-3b').click();
  await expect(page).toHaveURL(/#\/practice\/q3\?seed=1$/);
  await expect(page.getByTestId('variant-seed')).toHaveText('1');
  await openScene(page, '#/ray-sphere');
  await page.getByTestId('practise-fresh-5').click();
  await expect(page.getByTestId('variant-seed')).toHaveText(/^\d+$/);
  await expect(page).toHaveURL(/#\/practice\/q5\?seed=\d+/);
});
