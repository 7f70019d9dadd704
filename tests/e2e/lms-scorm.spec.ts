/**
 * SCORM 1.2 and 2004 packages with scorm-again playing the LMS: a host page provides the API and
 * opens the package's launch page in a frame; the learner answers a question (all right but one
 * answer with a named mistake); the LMS's data model then holds the score, the status, one
 * interaction per answer (the mistake named) and suspend_data. A second launch with the saved data
 * resumes the typed answers, and the learner's variant is the same.
 */
import { readFileSync } from 'node:fs';
import type { Server } from 'node:http';
import type { Frame, Page } from '@playwright/test';
import { test, expect, giveAnswer } from './fixtures';
import { haveSingle, packages, serve, unzip } from './lmsHost';
import { variantOf } from '../../src/lms/grade';
import { learnerSeed } from '../../src/lms/seeds';
import { expectedText } from '../../src/practice/check';
import { allAnswers } from '../../src/practice/model';

let ORIGIN = '';
const PKG_SEED = 11;
let server: Server | null = null;

const HOST = (
  lib: string,
  global: string,
  apiName: string,
) => `<!doctype html><html><head><meta charset="utf-8"><title>LMS</title>
<script src="/scorm-again/${lib}"></script></head><body><p id="lms">test LMS</p><script>
window.launch = function (init) {
  var api = new ${global}({ autocommit: false, logLevel: 5 });
  if (init.json) api.loadFromJSON(init.json, '');
  init.setup(api);
  window.commits = 0;
  api.on('${apiName === 'API' ? 'LMSCommit' : 'Commit'}', function () { window.commits++; });
  window.${apiName} = api;
  var f = document.createElement('iframe');
  f.name = 'sco'; f.src = init.src; f.style.width = '1200px'; f.style.height = '800px';
  document.body.appendChild(f);
};
window.cmi = function () { return JSON.parse(JSON.stringify(window.${apiName}.cmi)); };
</script></body></html>`;

test.beforeAll(async () => {
  test.skip(!haveSingle(), 'needs the single-file build (npm run build:single)');
  const files = new Map<string, Uint8Array | string>();
  for (const [kind, zip] of [
    ['12', packages(['q5'], PKG_SEED)['practice-scorm12.zip']],
    ['2004', packages(['q5'], PKG_SEED)['practice-scorm2004.zip']],
  ] as const)
    for (const [name, bytes] of Object.entries(unzip(zip))) files.set(`/pkg${kind}/${name}`, bytes);
  files.set('/scorm-again/scorm12.js', readFileSync('node_modules/scorm-again/dist/scorm12.js'));
  files.set('/scorm-again/scorm2004.js', readFileSync('node_modules/scorm-again/dist/scorm2004.js'));
  files.set('/favicon.ico', '');
  files.set('/host12.html', HOST('scorm12.js', 'Scorm12API', 'API'));
  files.set('/host2004.html', HOST('scorm2004.js', 'Scorm2004API', 'API_1484_11'));
  ({ server, origin: ORIGIN } = await serve(files));
});

test.afterAll(async () => {
  await new Promise<void>((ok) => (server ? server.close(() => ok()) : ok()));
});

async function sco(page: Page): Promise<Frame> {
  await expect
    .poll(() => page.frame({ name: 'sco' })?.url() ?? '', { timeout: 30_000 })
    .toContain('/index.html');
  const f = page.frame({ name: 'sco' })!;
  await expect(f.getByTestId('lms-status')).toHaveAttribute('data-state', 'connected', { timeout: 30_000 });
  await expect(f.getByTestId('variant-seed')).toBeVisible({ timeout: 30_000 });
  return f;
}

for (const version of ['12', '2004'] as const) {
  test(`SCORM ${version === '12' ? '1.2' : '2004'}: score, status, interactions, suspend_data, resume`, async ({
    page,
  }) => {
    test.setTimeout(120_000);
    const learner = `learner-${version}`;
    const seed = learnerSeed(learner, 'q5', PKG_SEED);
    const v = variantOf('q5', seed);
    const answers = allAnswers(v);
    const wrong = answers.find((a) => a.kind === 'number' && a.mistakes.length > 0);
    expect(wrong, 'a q5 answer with a named mistake').toBeTruthy();
    const mistake = wrong!.kind === 'number' ? wrong!.mistakes[0] : null;

    const launch = async (json: unknown) => {
      await page.goto(`${ORIGIN}/host${version}.html`);
      await page.evaluate(
        ({ json, learner, version, src }) => {
          (window as unknown as { launch: (i: unknown) => void }).launch({
            json,
            src,
            setup: (api: { cmi: Record<string, Record<string, unknown>> }) => {
              if (version === '12') {
                api.cmi.core.student_id = learner;
                api.cmi.core.student_name = 'Learner, Test';
                if (!json) api.cmi.student_data.mastery_score = '80';
              } else {
                (api.cmi as unknown as Record<string, unknown>).learner_id = learner;
                (api.cmi as unknown as Record<string, unknown>).learner_name = 'Test Learner';
                if (!json) (api.cmi as unknown as Record<string, unknown>).scaled_passing_score = '0.8';
              }
            },
          });
        },
        { json, learner, version, src: `/pkg${version}/index.html` },
      );
      return sco(page);
    };

    let f = await launch(null);
    await expect(f.getByTestId('variant-seed')).toHaveText(String(seed));
    for (const a of answers)
      await giveAnswer(f, a.name, a === wrong ? String(mistake!.value) : expectedText(a));
    await f.getByRole('button', { name: 'Check' }).click();
    await expect(f.getByTestId(`verdict-${wrong!.name}`)).toHaveAttribute(
      'data-value',
      `mistake:${mistake!.id}`,
    );
    await expect
      .poll(() => page.evaluate(() => (window as unknown as { commits: number }).commits))
      .toBeGreaterThan(0);

    const cmi = (await page.evaluate(() => (window as unknown as { cmi: () => unknown }).cmi())) as Record<
      string,
      any
    >;
    const n = answers.length;
    // scorm-again's JSON writes lists as objects keyed 0, 1, …
    const interactions: any[] = Object.values(cmi.interactions ?? {});
    expect(interactions).toHaveLength(n);
    const wrongI = interactions.find((i: any) =>
      String(i.id).endsWith(`${version === '12' ? '-' : ':'}${wrong!.name}`),
    );
    expect(wrongI).toBeTruthy();
    if (version === '12') {
      expect(cmi.core.score.raw).toBe(String(Math.round(((n - 1) / n) * 10000) / 100));
      expect(cmi.core.score.max).toBe('100');
      expect(cmi.core.lesson_status).toBe((n - 1) / n >= 0.8 ? 'passed' : 'failed');
      expect(wrongI.result).toBe('wrong');
      expect(wrongI.student_response).toBe(String(mistake!.value));
      expect((Object.values(wrongI.objectives)[0] as any).id).toBe(`mistake-${mistake!.id}`);
      expect(interactions.filter((i: any) => i.result === 'correct')).toHaveLength(n - 1);
    } else {
      expect(cmi.score.raw).toBe(String(n - 1));
      expect(cmi.score.max).toBe(String(n));
      expect(Number(cmi.score.scaled)).toBeCloseTo((n - 1) / n, 5);
      expect(cmi.completion_status).toBe('completed');
      expect(cmi.success_status).toBe((n - 1) / n >= 0.8 ? 'passed' : 'failed');
      expect(wrongI.result).toBe('incorrect');
      expect(wrongI.learner_response).toBe(String(mistake!.value));
      expect(wrongI.description).toContain(`mistake ${mistake!.id}`);
      expect(interactions.filter((i: any) => i.result === 'correct')).toHaveLength(n - 1);
    }
    const suspend = String(cmi.suspend_data);
    expect(suspend.length).toBeLessThanOrEqual(version === '12' ? 4096 : 64000);
    const saved = JSON.parse(suspend);
    expect(saved.q.q5.s).toBe(seed);
    expect(saved.q.q5.a[wrong!.name]).toBe(String(mistake!.value));

    // a typed but unchecked change also reaches suspend_data; leaving the page terminates
    const last = answers.filter((a) => a.kind !== 'choice').at(-1)!;
    await f.getByTestId(`answer-${last.name}`).fill('edited');
    await f.evaluate(() => (window.location.href = 'about:blank'));
    await expect
      .poll(async () => {
        const c = (await page.evaluate(() => (window as unknown as { cmi: () => any }).cmi())) as any;
        return version === '12' ? c.core.exit : c.exit;
      })
      .toBe('suspend');
    const after = (await page.evaluate(() => (window as unknown as { cmi: () => any }).cmi())) as any;
    expect(JSON.parse(after.suspend_data).q.q5.a[last.name]).toBe('edited');

    // relaunch with the saved data: same variant, answers back
    const resume =
      version === '12'
        ? {
            suspend_data: after.suspend_data,
            core: { entry: 'resume', lesson_status: after.core.lesson_status },
          }
        : { suspend_data: after.suspend_data, entry: 'resume', completion_status: after.completion_status };
    f = await launch(resume);
    await expect(f.getByTestId('variant-seed')).toHaveText(String(seed));
    await expect(f.getByTestId(`answer-${wrong!.name}`)).toHaveValue(String(mistake!.value));
    await expect(f.getByTestId(`answer-${last.name}`)).toHaveValue('edited');
    const other = answers.find((a) => a !== wrong && a !== last)!;
    await expect(f.getByTestId(`answer-${other.name}`)).toHaveValue(expectedText(other));
  });
}

test('without an LMS the package runs as the normal practice pages', async ({ page }) => {
  await page.goto(`${ORIGIN}/pkg12/index.html`);
  await expect(page.getByTestId('lms-status')).toHaveAttribute('data-state', 'none', { timeout: 30_000 });
  await expect(page).toHaveURL(/#\/practice\/q5/);
  await expect(page.getByTestId('variant-seed')).toBeVisible();
  await page.getByTestId('answer-a').fill('1');
  await page.getByRole('button', { name: 'Check' }).click();
  await expect(page.getByTestId('verdict-a')).toHaveAttribute('data-value', /.+/);
});
