/**
 * What only a page shows of the trust fixes (the logic is unit-tested in tests/results, tests/app,
 * tests/lms and tests/practice):
 *  - #/results checks files in its worker: the file input is disabled while busy, a file dropped
 *    meanwhile waits its turn and is counted, a file that is not a results file is named, Cancel
 *    stops a batch and leaves the earlier results; and in this production build `fuzz=1` in the
 *    link starts nothing;
 *  - with a route's stylesheet gone (a deploy replaced the build), #/results and #/guide say they
 *    could not be loaded, and after a deploy the page reloads once onto the new build and then says
 *    so: never a blank page.
 */
import { copyFileSync, readdirSync, readFileSync, rmSync, unlinkSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { test as base, type Page } from '@playwright/test';
import { test, expect } from './fixtures';
import { serveBuildCopy } from './buildCopy';
import { variantOf } from '../../src/lms/grade';
import { expectedText } from '../../src/practice/check';
import { allAnswers } from '../../src/practice/model';
import { RESULTS_FORMAT } from '../../src/results/format';

const dist = process.env.E2E_DIST ?? 'dist';

/** A results file of `n` attempts at Q1 (each its own variant, answered right but the last answer). */
function resultsFile(name: string, student: string, n: number) {
  const attempts = Array.from({ length: n }, (_, i) => {
    const seed = 1000 + i;
    const answers = allAnswers(variantOf('q1', seed));
    return {
      question: 'q1',
      seed,
      time: `2026-01-01T00:${String(Math.floor(i / 60) % 60).padStart(2, '0')}:${String(i % 60).padStart(2, '0')}Z`,
      answers: Object.fromEntries(
        answers.map((a, k) => [a.name, k < answers.length - 1 ? expectedText(a) : '1']),
      ),
      verdicts: {},
    };
  });
  const text = JSON.stringify({
    format: RESULTS_FORMAT,
    formatVersion: 1,
    app: 't',
    student,
    created: '',
    attempts,
  });
  return { name, mimeType: 'application/json', buffer: Buffer.from(text) };
}

test('#/results: busy in its worker, a dropped file waits its turn, Cancel keeps the earlier results; no fuzzer', async ({
  page,
}) => {
  // a production build: a link asking for the fuzzer starts nothing (its code is not even built)
  expect(readdirSync(`${dist}/assets`).filter((f) => /fuzz/i.test(f))).toEqual([]);
  // the results worker's messages can be held until the test lets them through, so that a file can
  // be dropped while a batch is surely still being checked
  await page.addInitScript(() => {
    const w = window as unknown as { __hold: boolean; __held: (() => void)[]; __release: () => void };
    w.__hold = false;
    w.__held = [];
    w.__release = () => {
      w.__hold = false;
      for (const send of w.__held.splice(0)) send();
    };
    const Orig = window.Worker;
    window.Worker = class extends Orig {
      private readonly results: boolean;
      constructor(url: string | URL, options?: WorkerOptions) {
        super(url, options);
        this.results = /results\.worker/.test(String(url));
      }
      override postMessage(msg: unknown, transfer?: Transferable[] | StructuredSerializeOptions) {
        const send = () => super.postMessage(msg, transfer as Transferable[]);
        if (this.results && w.__hold) w.__held.push(send);
        else send();
      }
    };
  });
  await page.goto('./#/results?fuzz=1&seed=3&fuzzn=50');
  const main = page.locator('main#main');
  await expect(main).toHaveAttribute('data-ready', '1', { timeout: 30_000 });
  const input = page.getByTestId('results-files');
  const status = page.getByTestId('results-status');
  const report = page.getByTestId('results-report');
  type Held = { __hold: boolean; __held: unknown[]; __release: () => void };
  /** From now on the results worker's messages wait (see the init script above). */
  const hold = () => page.evaluate(() => ((window as unknown as Held).__hold = true));
  /** Resolves once a message to the worker is waiting: the batch is surely still being checked. */
  const untilHeld = () =>
    expect.poll(() => page.evaluate(() => (window as unknown as Held).__held.length)).toBeGreaterThan(0);
  /** The waiting messages go, and later ones are no longer held. */
  const release = () => page.evaluate(() => (window as unknown as Held).__release());

  await hold();
  await input.setInputFiles([
    {
      name: 'broken.json',
      mimeType: 'application/json',
      buffer: Buffer.from('{"format": "render-math-lab-res'),
    },
    resultsFile('ada.json', 'Ada', 250),
  ]);
  await untilHeld();
  await expect(input).toBeDisabled();
  await expect(page.getByTestId('results-cancel')).toBeVisible();
  // a file dropped while the batch is checked is queued, not lost
  const late = resultsFile('bob.json', 'Bob', 1);
  const drop = await page.evaluateHandle(
    ({ name, text }) => {
      const dt = new DataTransfer();
      dt.items.add(new File([text], name, { type: 'application/json' }));
      return dt;
    },
    { name: late.name, text: late.buffer.toString('utf8') },
  );
  // every text the status takes, recorded in the page (the queued state may last less than a poll)
  await page.evaluate(() => {
    const el = document.querySelector('[data-testid="results-status"]')!;
    const w = window as unknown as { __statuses: string[] };
    w.__statuses = [el.textContent ?? ''];
    new MutationObserver(() => w.__statuses.push(el.textContent ?? '')).observe(el, {
      childList: true,
      characterData: true,
      subtree: true,
    });
  });
  await page.getByTestId('results-drop').dispatchEvent('drop', { dataTransfer: drop });
  await expect(status).toContainText('1 more waiting');
  await release();
  await expect(report).toHaveAttribute('data-files', '3', { timeout: 60_000 });
  await expect(report).toHaveAttribute('data-attempts', '251');
  await expect(report).toHaveAttribute('data-students', '2');
  await expect(page.getByTestId('results-problems')).toContainText('broken.json: not JSON');
  await expect(input).toBeEnabled();
  const statuses = await page.evaluate(() => (window as unknown as { __statuses: string[] }).__statuses);
  expect(
    statuses.some((t) => t.includes('1 more waiting')),
    statuses.join(' | '),
  ).toBe(true);

  // Cancel: the batch stops, the page keeps what it had, and the next batch works (the batch is
  // held, as above, so that it is surely still being checked when Cancel is pressed)
  await hold();
  await input.setInputFiles(['cy', 'dan', 'eve', 'fay'].map((n) => resultsFile(`${n}.json`, n, 300)));
  await untilHeld();
  await expect(status).toContainText('Checking');
  await page.getByTestId('results-cancel').dispatchEvent('click');
  await expect(page.getByTestId('results-problems')).toContainText('Checking was cancelled');
  await expect(input).toBeEnabled();
  await expect(report).toHaveAttribute('data-files', '3');
  // what was held goes to the cancelled batch's worker, which has been ended (nothing arrives)
  await release();
  await input.setInputFiles([resultsFile('di.json', 'Di', 2)]);
  await expect(report).toHaveAttribute('data-files', '4', { timeout: 30_000 });
  await expect(report).toHaveAttribute('data-students', '3');

  await expect(page.locator('.fuzz-panel')).toHaveCount(0);
  expect(await page.evaluate(() => '__rmlFuzz' in window)).toBe(false);
});

/** Errors thrown in the page (a missing file's 404 is the test's doing, not the page's). */
function pageErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(e.message));
  return errors;
}

base(
  'a route whose stylesheet is gone says so, and after a deploy reloads once onto the new build',
  async ({ page }) => {
    const srv = await serveBuildCopy();
    try {
      const assets = join(srv.dir, 'assets');
      for (const f of readdirSync(assets))
        if (/^(ResultsRoute|Guide)-.*\.css$/.test(f)) unlinkSync(join(assets, f));
      const errors = pageErrors(page);
      for (const [hash, what] of [
        ['#/results', 'The class results page'],
        ['#/guide', 'The guide'],
      ]) {
        await page.goto(`${srv.base}${hash}`);
        await expect(page.getByTestId('route-load-failed')).toContainText(`${what} could not be loaded`);
        await expect(
          page.getByTestId('route-load-failed').getByRole('button', { name: 'reload' }),
        ).toBeVisible();
      }

      // a page of the old build is open on #/ (a new document); a new build is deployed (another
      // entry script); the reader opens #/results: the page reloads onto the new build, whose results
      // page cannot load either (its stylesheet is still gone), and says so instead of reloading again
      const old = await page.context().newPage();
      const oldErrors = pageErrors(old);
      await old.goto(`${srv.base}#/`);
      await expect(old.locator('main#main')).toBeVisible();
      await old.evaluate(() => ((window as unknown as { oldPage: boolean }).oldPage = true));
      const index = readFileSync(join(srv.dir, 'index.html'), 'utf8');
      const entry = /src="\.\/assets\/(index-[^"]+\.js)"/.exec(index)![1];
      copyFileSync(join(assets, entry), join(assets, 'index-next.js'));
      writeFileSync(join(srv.dir, 'index.html'), index.replace(entry, 'index-next.js'));
      await old.evaluate(() => (window.location.hash = '#/results'));
      await expect(old.getByTestId('route-load-failed')).toContainText(
        'The class results page could not be loaded',
      );
      expect(await old.evaluate(() => 'oldPage' in window)).toBe(false);
      expect(
        await old.evaluate(() => [...document.scripts].some((s) => s.src.endsWith('/index-next.js'))),
      ).toBe(true);
      expect(oldErrors).toEqual([]);
      expect(errors).toEqual([]);
    } finally {
      await srv.stop();
      rmSync(srv.dir, { recursive: true, force: true });
    }
  },
);
