/**
 * The pages that are not scenes, as a reader meets them: each in one pass (./wholePage.ts) — axe
 * (WCAG 2.2 AA) light at 1280 px and dark at 375 px, target sizes, reflow at 320 px, text
 * spacing, focus never hidden and its ring visible, no caret in the visible text; a practice page
 * with its answers checked, so that its verdicts and feedback are scanned too. The scenes get the
 * same pass in catalogue.spec.ts.
 */
import type { Page } from '@playwright/test';
import { QUESTIONS } from '../../src/kit/catalogue';
import { allAnswers, type AnswerSpec } from '../../src/practice/model';
import { questionInfo } from '../../src/practice/questions';
import { test, expect, giveAnswer, openScene } from './fixtures';
import { checkWholePage, visibleCarets } from './wholePage';

test.describe.configure({ timeout: 240_000 });

/**
 * A practice question checked, its verdicts and feedback shown: half its answers right, half a
 * plain "1" (wrong or invalid).
 */
async function checkHalfRight(page: Page): Promise<void> {
  const v = questionInfo('q3').generate(17);
  const answers = allAnswers(v);
  const right = (a: AnswerSpec) =>
    a.kind === 'number'
      ? a.expected === null
        ? 'none'
        : a.expected.toPrecision(5)
      : a.kind === 'formula'
        ? a.expectedText
        : a.expected;
  for (const [i, a] of answers.entries()) await giveAnswer(page, a.name, i % 2 ? right(a) : '1');
  await page.getByRole('button', { name: 'Check', exact: true }).click();
  for (const a of answers)
    await expect(page.getByTestId(`verdict-${a.name}`)).toHaveAttribute('data-value', /.+/);
}

const PAGES: [string, ((page: Page) => Promise<void>)?][] = [
  ['#/'],
  ['#/guide'],
  ['#/practice'],
  ['#/practice/q3?seed=17', checkHalfRight],
  ['#/accessibility'],
  ['#/results'],
];

for (const [route, prepare] of PAGES) {
  test(`${route}${prepare ? ', checked' : ''}: the whole page in both themes and at both widths`, async ({
    page,
  }) => {
    await checkWholePage(page, route, { prepare });
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
