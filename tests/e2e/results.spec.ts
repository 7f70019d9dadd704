/**
 * #/results collates 100 generated results files offline (the context is set offline once the
 * page is ready, and no request is made after that) in under 60 s, and its counts (attempts,
 * named mistakes per question, each student's best score) equal what the files contain. One file
 * claims "correct" for answers that are mistakes: the recomputed verdicts count.
 */
import { test, expect, giveAnswer } from './fixtures';
import { variantOf } from '../../src/lms/grade';
import { expectedText } from '../../src/practice/check';
import { allAnswers, QUESTION_IDS, type QuestionId } from '../../src/practice/model';
import { RESULTS_FORMAT } from '../../src/results/format';

/** A small seeded generator (mulberry32), so the files are the same every run. */
function rng(seed: number) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

interface Expected {
  attempts: Record<string, number>;
  mistakes: Record<string, number>;
  best: { score: number; max: number }[][];
}

function generate(nFiles: number): {
  files: { name: string; mimeType: string; buffer: Buffer }[];
  want: Expected;
} {
  const r = rng(2024);
  const want: Expected = { attempts: {}, mistakes: {}, best: [] };
  const files = [];
  for (let f = 0; f < nFiles; f++) {
    const attempts = [];
    const best: Record<string, { score: number; max: number }> = {};
    const tamper = f === 7;
    const qs = QUESTION_IDS.filter(() => r() < 0.5);
    if (!qs.length) qs.push(QUESTION_IDS[f % 6]);
    for (const q of qs as QuestionId[]) {
      const seed = Math.floor(r() * 100000);
      const answers = allAnswers(variantOf(q, seed));
      const tries = 1 + Math.floor(r() * 2);
      for (let k = 0; k < tries; k++) {
        const typed: Record<string, string> = {};
        const verdicts: Record<string, string> = {};
        let score = 0;
        // at most one mistake per attempt: the checker's follow-through may re-judge an answer that
        // builds on an earlier wrong one, so a second mistake's verdict would not be the file's
        let mistakes = 0;
        for (const a of answers) {
          const x = r();
          const ms = a.kind === 'number' || a.kind === 'choice' ? a.mistakes : [];
          if (ms.length && mistakes === 0 && (x < 0.3 || tamper)) {
            mistakes++;
            const m = ms[Math.floor(r() * ms.length)];
            typed[a.name] = String(m.value);
            verdicts[a.name] = tamper ? 'correct' : `mistake:${m.id}`;
            const key = `${q}/${m.id}`;
            want.mistakes[key] = (want.mistakes[key] ?? 0) + 1;
          } else if (x < 0.9) {
            typed[a.name] = expectedText(a);
            verdicts[a.name] = 'correct';
            score++;
          } // else blank
        }
        // each attempt at its own second: the page counts an attempt found twice (same question,
        // seed, time and answers) once
        const time = new Date(Date.UTC(2025, 0, 1, 10, 0, attempts.length)).toISOString();
        attempts.push({ question: q, seed, time, answers: typed, verdicts });
        want.attempts[q] = (want.attempts[q] ?? 0) + 1;
        const key = `${q}:${seed}`;
        if (!best[key] || score > best[key].score) best[key] = { score, max: answers.length };
      }
    }
    want.best.push(
      QUESTION_IDS.map(
        (q) => Object.entries(best).find(([k]) => k.startsWith(`${q}:`))?.[1] ?? { score: -1, max: 0 },
      ),
    );
    const body = {
      format: RESULTS_FORMAT,
      formatVersion: 1,
      app: 'test',
      student: `Student ${f + 1}`,
      created: '2025-01-01T10:00:00Z',
      attempts,
    };
    files.push({
      name: `student-${f + 1}.json`,
      mimeType: 'application/json',
      buffer: Buffer.from(JSON.stringify(body)),
    });
  }
  return { files, want };
}

test('#/results collates 100 files offline, recomputing every verdict', async ({ page }) => {
  test.setTimeout(120_000);
  const { files, want } = generate(100);
  // no service worker in this page (tests/e2e/offline.spec.ts covers it): the shell would load its
  // registration chunk when the page goes quiet, which is the shell's request, not this page's
  await page.addInitScript(() => {
    delete (Navigator.prototype as { serviceWorker?: unknown }).serviceWorker;
  });
  await page.goto('./#/results');
  await expect(page.locator('main#main')).toHaveAttribute('data-ready', '1', { timeout: 30_000 });
  await page.context().setOffline(true);
  const requests: string[] = [];
  page.on('request', (req) => {
    if (!/^(blob|data):/.test(req.url())) requests.push(req.url());
  });
  await page.getByTestId('results-files').setInputFiles(files);
  const report = page.getByTestId('results-report');
  await expect(report).toHaveAttribute('data-files', '100', { timeout: 60_000 });
  const totalAttempts = Object.values(want.attempts).reduce((a, b) => a + b, 0);
  await expect(report).toHaveAttribute('data-attempts', String(totalAttempts));
  await expect(report).toHaveAttribute('data-students', '100');
  for (const q of QUESTION_IDS)
    if (want.attempts[q])
      await expect(page.getByTestId(`attempts-${q}`)).toHaveAttribute('data-value', String(want.attempts[q]));
  for (const [key, n] of Object.entries(want.mistakes)) {
    const [q, id] = key.split('/');
    await expect(page.getByTestId(`mistake-${q}-${id}`)).toHaveAttribute('data-value', String(n));
  }
  const shown = await page
    .locator('[data-testid^="mistake-q"]')
    .evaluateAll((els) => els.reduce((s, e) => s + Number(e.getAttribute('data-value')), 0));
  expect(shown).toBe(Object.values(want.mistakes).reduce((a, b) => a + b, 0));
  await expect(page.getByTestId('student-row')).toHaveCount(100);
  for (const i of [0, 7, 42, 99])
    for (const [k, q] of QUESTION_IDS.entries()) {
      const b = want.best[i][k];
      await expect(page.getByTestId(`student-${i}-${q}`)).toHaveAttribute(
        'data-value',
        b.score < 0 ? '' : `${b.score}/${b.max}`,
      );
    }
  // the tampered file (student 8) claimed "correct" for its mistakes
  await expect(page.locator('[data-testid^="disagree-"]').first()).toBeVisible();
  const download = page.waitForEvent('download');
  await page.getByTestId('export-csv').click();
  const csv = await (await download).createReadStream().then(async (s) => {
    const chunks: Buffer[] = [];
    for await (const c of s) chunks.push(c as Buffer);
    return Buffer.concat(chunks).toString('utf8');
  });
  expect(csv.trim().split('\r\n')).toHaveLength(101);
  expect(requests, 'no request after going offline').toEqual([]);
  await page.context().setOffline(false);
});

test('a practice page downloads the learner’s checks as a results file', async ({ page }) => {
  await page.goto('./#/practice/q5?seed=31');
  const a = allAnswers(variantOf('q5', 31))[0];
  await giveAnswer(page, a.name, expectedText(a));
  await page.getByRole('button', { name: 'Check' }).click();
  await expect(page.getByTestId(`verdict-${a.name}`)).toHaveAttribute('data-value', 'correct');
  await page.getByLabel('Your name').fill('Ada');
  const download = page.waitForEvent('download');
  await page.getByTestId('download-results-button').click();
  const d = await download;
  expect(d.suggestedFilename()).toMatch(/^render-math-lab-results-Ada-\d{4}-\d\d-\d\d\.json$/);
  const text = await d.createReadStream().then(async (s) => {
    const chunks: Buffer[] = [];
    for await (const c of s) chunks.push(c as Buffer);
    return Buffer.concat(chunks).toString('utf8');
  });
  const file = JSON.parse(text);
  expect(file).toMatchObject({ format: RESULTS_FORMAT, student: 'Ada' });
  expect(file.app).toMatch(/^\d+\.\d+\.\d+/);
  expect(file.attempts.at(-1)).toMatchObject({
    question: 'q5',
    seed: 31,
    answers: { [a.name]: expectedText(a) },
    verdicts: { [a.name]: 'correct' },
  });
  expect(typeof file.attempts.at(-1).time).toBe('string');
});
