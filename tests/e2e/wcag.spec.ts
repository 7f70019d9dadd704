/**
 * The pages that are not scenes, as a reader meets them: each in one pass (./wholePage.ts) — axe
 * (WCAG 2.2 AA) light at 1280 px and dark at 375 px, target sizes, reflow at 320 px, text
 * spacing, focus never hidden and its ring visible, no caret in the visible text; a practice page
 * with its answers checked and the results page with a report, so that verdicts, feedback and
 * reports are scanned too, and the render lab with every fold open (on the CPU renderer at its
 * smallest image, so that its folds' runs stay short). The scenes get the same pass in
 * catalogue.spec.ts; every practice question's text, its answers and worked solution
 * shown, is checked for carets in tests/render/practiceCarets.test.tsx.
 */
import type { Page } from '@playwright/test';
import { allAnswers, type AnswerSpec } from '../../src/practice/model';
import { expectedText } from '../../src/practice/check';
import { variantOf } from '../../src/lms/grade';
import { RESULTS_FORMAT } from '../../src/results/format';
import { questionInfo } from '../../src/practice/questions';
import { test, expect, giveAnswer } from './fixtures';
import { checkWholePage } from './wholePage';

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

/**
 * The results page with a report shown: two students' files, and two files it cannot read, named
 * in its problems.
 */
async function loadResults(page: Page): Promise<void> {
  await expect(page.locator('main#main')).toHaveAttribute('data-ready', '1', { timeout: 30_000 });
  const file = (student: string, seed: number) => {
    const v = variantOf('q5', seed);
    const answers = Object.fromEntries(allAnswers(v).map((a) => [a.name, expectedText(a)]));
    const body = { format: RESULTS_FORMAT, formatVersion: 1, app: 't', student, created: '' };
    const attempts = [{ question: 'q5', seed, time: '2026-01-01T00:00:00Z', answers, verdicts: {} }];
    return {
      name: `${student}.json`,
      mimeType: 'application/json',
      buffer: Buffer.from(JSON.stringify({ ...body, attempts })),
    };
  };
  await page
    .getByTestId('results-files')
    .setInputFiles([
      file('ada', 3),
      file('bob', 4),
      { name: 'notes.json', mimeType: 'application/json', buffer: Buffer.from('{"hello": 1}') },
      { name: 'photo.json', mimeType: 'application/json', buffer: Buffer.from([0xff, 0xd8, 0xff]) },
    ]);
  await expect(page.getByTestId('results-report')).toHaveAttribute('data-students', '2');
  const problems = page.getByTestId('results-problems');
  await expect(problems).toContainText('notes.json: not a Render Math Lab results file');
  await expect(problems).toContainText('photo.json: not JSON');
}

const PAGES: [string, ((page: Page) => Promise<void>)?][] = [
  ['#/'],
  ['#/guide'],
  ['#/practice'],
  ['#/practice/q3?seed=17', checkHalfRight],
  ['#/accessibility'],
  ['#/results', loadResults],
  // the render lab: every fold open (the equal-time fold at its shortest budget per strategy)
  ['#/render?renderer=cpu&res=32&spp=1&et=250'],
];

for (const [route, prepare] of PAGES) {
  test(`${route}${prepare ? `, ${prepare.name}` : ''}: the whole page in both themes and at both widths`, async ({
    page,
  }) => {
    await checkWholePage(page, route, { prepare });
  });
}
