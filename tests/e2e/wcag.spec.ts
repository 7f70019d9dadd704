/**
 * The pages that are not scenes, as a reader meets them: each in one pass (./wholePage.ts) — axe
 * (WCAG 2.2 AA) light at 1280 px and dark at 375 px, target sizes, reflow at 320 px, text
 * spacing, focus never hidden and its ring visible, no caret in the visible text. The scenes get
 * the same pass in catalogue.spec.ts.
 */
import { QUESTIONS } from '../../src/kit/catalogue';
import { test, expect, openScene } from './fixtures';
import { checkWholePage, visibleCarets } from './wholePage';

test.describe.configure({ timeout: 240_000 });

const PAGES = ['#/', '#/guide', '#/practice', '#/practice/q1?seed=3', '#/accessibility', '#/results'];

for (const route of PAGES) {
  test(`${route}: the whole page in both themes and at both widths`, async ({ page }) => {
    await checkWholePage(page, route);
  });
}

test('the practice questions: no caret in the statement, the feedback or the worked solution', async ({
  page,
}) => {
  for (const q of QUESTIONS) {
    await openScene(page, `#/practice/${q.practice.id}?seed=3`);
    // the statement, every part's prompt, the givens and the whole worked solution with its answers
    await page.getByTestId('show-solution').click();
    await expect(page.getByTestId('solution')).toBeVisible();
    expect(await visibleCarets(page), q.practice.id).toEqual([]);
  }
});
