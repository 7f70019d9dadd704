/**
 * Browser tests of #/hemisphere (exam Q1, Q2): the wiring (every readout of the exam page, of
 * Phong, of a low-discrepancy point set, of typed densities and of the key's inverted Jacobian
 * equals the scene's own model run here in Node, same core code, same seed and point set), the
 * folded settings with typed densities and their messages, the opening statistics waiting for
 * the page, and 200 000 points grown in the 3D view. Expected values come from closed forms
 * (k = 2/(e^{2π} − 1), ∫ cos θ dω = π, …) and from the model, never from the answer key.
 *
 * Elsewhere: the parts in exam order, the shared timeline (play, pause, the link restores t) and
 * the whole-page checks in catalogue.spec.ts; the description, the histogram table and the
 * keyboard in hemisphere-a11y.spec.ts; the GPU warp in hemisphere-gpu.spec.ts; each density
 * message's wording in tests/core/sampling/tabulatedHemisphere.test.ts and tests/core/expr.
 */
import type { Page } from '@playwright/test';
import { test, expect, followLinkAnew, openScene, readout, readoutNumber, waitForReadout } from './fixtures';
import { computeDrawStats } from '../../src/scenes/hemisphere/drawStats';
import { lobeFromParams, makeLobe } from '../../src/scenes/hemisphere/lobe';
import { animFrame } from '../../src/scenes/hemisphere/animation';
import { rmseOverRuns } from '../../src/scenes/hemisphere/q2Estimates';
import { examLobeK } from '../../src/core/sampling';
import { formatNumber } from '../../src/ui/Readout';
import type { LobeId } from '../../src/scenes/hemisphere/params';

const cosTheta = (t: number) => Math.cos(t);
const rel = (a: number, b: number) => Math.abs(a - b) / Math.max(1e-300, Math.abs(b));

/** Open a scene without waiting for its deferred sections (the page is still loading). */
async function openSceneNoWait(page: Page, hash: string) {
  await page.goto(`./${hash}`);
  await page.waitForSelector('[data-testid="stats-status"]');
}

/** Wait until the worker's statistics for the current parameters are on screen. */
async function statsReady(page: Page) {
  await expect(page.getByTestId('stats-status')).toHaveAttribute('data-state', 'ready', { timeout: 30_000 });
}

async function expectMatchesCore(
  page: Page,
  lobeId: LobeId,
  n: number,
  seed: number,
  exponent = 8,
  custom?: (t: number, p: number) => number,
) {
  const built = lobeFromParams(lobeId, exponent, custom);
  if (built.tab && !built.tab.ok) throw new Error(built.tab.message);
  const lobe = built.lobe!;
  const core = computeDrawStats(lobe, cosTheta, 'independent', seed, n);
  // a link followed on the open page renders a moment later: wait for this lobe's k
  await waitForReadout(page, lobeId === 'exam' ? 'k' : 'k-chosen', (v) => Number(v) === lobe.k);
  // a link followed on the open page: the previous draw's "ready" may be seen before the new run
  // starts, so wait for this draw's count (each call here has its own n), then for its statistics
  await waitForReadout(page, 'samples', (v) => Number(v) === n);
  await statsReady(page);
  expect(rel(await readoutNumber(page, 'chi2-p'), core.chi2!.pValue)).toBeLessThan(1e-9);
  expect(rel(await readoutNumber(page, 'mc-exact'), core.exact)).toBeLessThan(1e-12);
  expect(rel(await readoutNumber(page, 'mc-uniform'), core.q2.uniform.estimate)).toBeLessThan(1e-12);
  expect(rel(await readoutNumber(page, 'mc-importance'), core.q2.importance.estimate)).toBeLessThan(1e-12);
  return core;
}

test('wiring: the exam page, the settings fold, Phong, sobol points, typed and bad densities, the inverted Jacobian equal the core', async ({
  page,
}) => {
  test.setTimeout(180_000);
  await openScene(page, '#/hemisphere?n=2000');
  await test.step('the exam: k, χ², the estimates and each part’s derivation', async () => {
    await statsReady(page);
    // the exam's answer (a): k = 2/(e^{2π} − 1)
    expect(Number(await readout(page, 'k'))).toBe(examLobeK());
    const core = await expectMatchesCore(page, 'exam', 2000, 1);
    expect(core.chi2!.pass).toBe(true);
    await expect(page.getByTestId('chi2-verdict')).toContainText('Accepted');
    await expect(page.getByTestId('derivation')).toContainText('Normalize');
    // Q1a: the identity, each evaluation step, and the live k
    const s1a = page.getByTestId('steps-1a');
    await expect(s1a).toContainText('sin θ cos θ = ½ sin 2θ');
    await expect(s1a).toContainText('antiderivative');
    await expect(s1a).toContainText(formatNumber(examLobeK(), 8));
    await expect(s1a).toContainText('radius of the ring');
    await expect(page.locator('main')).not.toContainText('area of a thin ring');
    await expect(page.getByTestId('answer-1a').getByTestId('k')).toHaveAttribute(
      'data-value',
      String(examLobeK()),
    );
    // Q1b: both marginals, the paper's identity credited, the key's 2 cot θ and its divergence,
    // the key's stray e^φ (with a space after it)
    await expect(page.getByTestId('steps-1b-theta')).toContainText('sin 2');
    await expect(page.getByTestId('steps-1b-phi')).toContainText('separable');
    await expect(page.getByTestId('paper-identity')).toContainText('printed');
    await expect(page.getByTestId('paper-identity')).toContainText('leniently');
    await expect(page.getByTestId('steps-1b-paper')).toContainText('2\\cot\\theta');
    await expect(page.getByTestId('steps-1b-paper')).toContainText('not integrable');
    await expect(page.getByTestId('keynote-stray-ephi')).toContainText('eφ outside the integral');
    await expect(page.getByTestId('keynote-stray-ephi')).toContainText('survives one more line');
    await expect(page.locator('main')).not.toContainText('see below');
    // Q1c, Q1d: CDF check at the first sample, both θ forms and the φ form with its numbers
    await expect(page.getByTestId('steps-1c-theta')).toContainText('sin^2');
    // the key's form θ = ½ cos⁻¹(1 − 2ξ₁), read in the MathML
    await expect(page.getByTestId('steps-1d-theta')).toContainText(/cos\u2061?−1\(1−2ξ1\)/);
    await expect(page.getByTestId('steps-1d-theta')).toContainText('\\sin^{-1}');
    await expect(page.getByTestId('steps-1d-phi')).toContainText('log1p');
    const f = animFrame(makeLobe('exam', 8), 'independent', 1, 2000, 'warp', 1);
    await expect(page.getByTestId('steps-1d-example')).toContainText(
      formatNumber(Math.asin(Math.sqrt(f.tracked!.xi1)), 12),
    );
    // Q2a: why |D| = 2π, with the quadrature value
    await expect(page.getByTestId('steps-2a')).toContainText('solid angle');
    await expect(page.getByTestId('steps-2a')).toContainText(formatNumber(2 * Math.PI, 12));
    // Q2c: the proof written out, and the key's E[X] flagged
    const s2c = page.getByTestId('steps-2c');
    await expect(s2c).toContainText('linearity of expectation');
    await expect(s2c).toContainText('law of the unconscious statistician');
    await expect(s2c).toContainText('p(x) > 0');
    await expect(page.getByTestId('keynote-eg')).toContainText('E[g(X)]');
  });

  await test.step('closed on load, opened by a click that writes open=settings; the link keeps it open', async () => {
    const fold = page.getByTestId('fold-settings');
    await expect(fold).not.toHaveAttribute('open');
    await expect(page.getByTestId('lobe')).toHaveCount(0);
    await fold.locator('summary').click();
    await expect(page).toHaveURL(/[?&]open=settings(&|$)/);
    await expect(page.getByTestId('lobe')).toBeVisible();
    await followLinkAnew(page);
    await expect(page.getByTestId('fold-settings')).toHaveAttribute('open');
  });

  await test.step('the lobe select writes the URL; the readouts follow', async () => {
    await statsReady(page);
    await page.getByTestId('lobe').selectOption('uniform');
    await expect(page).toHaveURL(/lobe=uniform/);
    // the chosen density's k is in the note naming it; Q1(a)'s answer keeps the exam's k
    await waitForReadout(page, 'k-chosen', (v) => Number(v) === 1 / (2 * Math.PI));
    expect(Number(await readout(page, 'k'))).toBe(examLobeK());
    await expectMatchesCore(page, 'uniform', 2000, 1);
  });

  await test.step('a density typed in the field is sampled', async () => {
    await page.getByTestId('lobe').selectOption('custom');
    const input = page.getByTestId('pdf-input');
    await input.fill('1');
    await input.press('Enter');
    await expect(page).toHaveURL(/pdf=1/);
    await waitForReadout(page, 'k-chosen', (v) => Math.abs(Number(v) * 2 * Math.PI - 1) < 1e-9);
    await statsReady(page);
    expect(Number(await readout(page, 'samples'))).toBe(2000);
  });

  // one density that is not a density (negative) and one that does not parse; the message of every
  // kind (negative, not integrable, not finite, zero) is a unit test of the tabulation
  await test.step('bad densities: a clear message each, nothing sampled, the rest works; fixing it recovers', async () => {
    const input = page.getByTestId('pdf-input');
    for (const [pdf, message] of [
      ['cos(theta) - 0.5', /negative/],
      ['cos(theta', /syntax|parenthesis|expected/i],
    ] as const) {
      await input.fill(pdf);
      await input.press('Enter');
      await expect(page.getByTestId('custom-error'), pdf).toContainText(message);
      await waitForReadout(page, 'samples', (v) => v === 'none');
      await statsReady(page);
      // no chosen density, so no k of its own; Q1(a)'s answer is still the exam's
      await expect(page.getByTestId('k-chosen')).toHaveCount(0);
      expect(Number(await readout(page, 'k'))).toBe(examLobeK());
      expect(await readout(page, 'chi2-p'), pdf).toBe('none');
      expect(await readout(page, 'mc-importance'), pdf).toBe('none');
      // Q2's exact value and the uniform estimate still work
      expect(rel(await readoutNumber(page, 'mc-exact'), Math.PI)).toBeLessThan(1e-12);
      await expect(page.locator('main')).not.toContainText('NaN');
    }
    await input.fill('cos(theta)');
    await input.press('Enter');
    await expect(page.getByTestId('custom-error')).toHaveCount(0);
    await waitForReadout(page, 'k-chosen', (v) => Math.abs(Number(v) * Math.PI - 1) < 1e-3);
  });

  await test.step('Phong n = 8 with f = cos θ: the core’s numbers, infinite variance, the repeat summary', async () => {
    await page.goto('./#/hemisphere?lobe=phong&exponent=8&n=1500&seed=7');
    await expectMatchesCore(page, 'phong', 1500, 7);
    await expect(page.getByTestId('variance-warning')).toContainText('Infinite variance');
    await expect(page.getByTestId('variance-warning')).toContainText('cos²⁻ⁿ');
    await expect(page.getByTestId('answer-2b').locator('.readout-note')).toContainText(
      'meaningless here (infinite variance)',
    );
    await page.getByTestId('repeat-button').click();
    const summary = page.getByTestId('repeat-summary');
    await expect(summary).toContainText('unbiased', { timeout: 60_000 });
    await expect(summary).toContainText('Phong');
    await expect(summary).not.toContainText('exam lobe');
  });

  // one low-discrepancy set stands for the three (the page's note takes the same path for each;
  // the RMSE of every set is a unit test of the model)
  await test.step('points=sobol: s/√N is not shown as the error; the RMSE over randomized runs is', async () => {
    await page.goto('./#/hemisphere?points=sobol&n=1024');
    await waitForReadout(page, 'samples', (v) => Number(v) === 1024);
    await statsReady(page);
    await expect(page.getByTestId('stderr-note')).toContainText('not an error estimate');
    const lobe = makeLobe('exam', 8)!;
    const core = computeDrawStats(lobe, cosTheta, 'sobol', 1, 1024);
    const r = rmseOverRuns(lobe, cosTheta, 'sobol', 1, 1024, core.exact);
    await expect(page.getByTestId('stderr-note')).toContainText(formatNumber(r.uniform, 3));
    const uniNote = page.getByTestId('answer-2a').locator('.readout-note');
    await expect(uniNote).toContainText(`RMSE ${formatNumber(r.uniform, 3)}`);
    await expect(uniNote).not.toContainText('std. error');
    await expect(page.getByTestId('answer-2b').locator('.readout-note')).toContainText(
      `RMSE ${formatNumber(r.importance, 3)}`,
    );
  });

  await test.step('typed densities: the core’s numbers, and k right to every digit printed', async () => {
    // the typed density's own derivation is folded under Explore further: the link opens it
    await page.goto('./#/hemisphere?lobe=custom&pdf=cos(theta)&n=1000&seed=3&open=lobe-derivation');
    await expectMatchesCore(page, 'custom', 1000, 3, 8, (t) => Math.cos(t));
    await expect(page.getByTestId('derivation')).toContainText('Numerical steps');
    // p ∝ cos³θ e^{φ/2}: ∫ p dω = ¼ · 2(e^π − 1), so k = 2/(e^π − 1); the exam's k stays the exam's
    await page.goto('./#/hemisphere?lobe=custom&n=1000&pdf=cos(theta)^3*exp(phi/2)');
    await expect(page.getByTestId('k-chosen')).toHaveText(formatNumber(2 / Math.expm1(Math.PI), 8));
    await expect(page.getByTestId('other-lobe')).toContainText('adaptive quadrature');
    await expect(page.getByTestId('answer-1a').getByTestId('k')).toHaveAttribute(
      'data-value',
      String(examLobeK()),
    );
  });

  await test.step('jacobian=inverted: a clear message, the divergence, nothing drawn, no garbage numbers', async () => {
    await page.goto('./#/hemisphere?jacobian=inverted');
    await expect(page.getByTestId('inverted-message')).toContainText('Not integrable');
    await waitForReadout(page, 'samples', (v) => v === 'none');
    await statsReady(page);
    expect(await readout(page, 'chi2-p')).toBe('none');
    expect(await readout(page, 'mc-importance')).toBe('none');
    // part (a) is unaffected, and so is the uniform estimator
    expect(Number(await readout(page, 'k'))).toBe(examLobeK());
    expect(rel(await readoutNumber(page, 'mc-exact'), Math.PI)).toBeLessThan(1e-12);
    // the partial integral −ln sin ε at the default ε = 1e-3
    const partial = await readoutNumber(page, 'inverted-partial');
    expect(rel(partial, -Math.log(Math.sin(1e-3)))).toBeLessThan(1e-12);
    await expect(page.locator('main')).not.toContainText('NaN');
    await expect(page.locator('main')).not.toContainText('Infinity');
    // the figure says nothing is drawn, and there is nothing to play
    await expect(page.getByTestId('hemi-caption').first()).toContainText('Nothing is drawn');
    await expect(
      page.getByTestId('timeline-nothing').getByRole('button', { name: /play/i }).first(),
    ).toBeDisabled();
  });
  await test.step('a bad integrand f from the link: its message, the estimates off, the rest works', async () => {
    await page.goto('./#/hemisphere?n=2000&f=' + encodeURIComponent('cos(theta'));
    await expect(page.locator('.expr-field [role=alert]').first()).toBeVisible();
    await waitForReadout(page, 'mc-uniform', (v) => v === 'none');
    await statsReady(page);
    expect(await readout(page, 'mc-importance')).toBe('none');
    expect(Number(await readout(page, 'k'))).toBe(examLobeK());
  });
});

test('the worker: the opening statistics wait for the page to load, a change before then runs at once; 200 000 points grow in the 3D view', async ({
  page,
}) => {
  test.setTimeout(180_000);
  // every state the status line shows, and when the statistics task goes to a worker, from the
  // start (the 3D view's points stream from a worker of their own at once: not logged)
  await page.addInitScript(() => {
    const w = window as unknown as { __log: string[] };
    w.__log = [];
    const Orig = window.Worker;
    window.Worker = class extends Orig {
      override postMessage(msg: unknown, transfer?: Transferable[] | StructuredSerializeOptions) {
        if ((msg as { method?: string } | null)?.method === 'stats')
          w.__log.push(document.documentElement.hasAttribute('data-settled') ? 'worker settled' : 'worker');
        super.postMessage(msg, transfer as Transferable[]);
      }
    };
    new MutationObserver(() => {
      const s = document.querySelector('[data-testid="stats-status"]')?.getAttribute('data-state');
      const settled = document.documentElement.hasAttribute('data-settled') ? ' settled' : '';
      if (s && w.__log.at(-1) !== s + settled) w.__log.push(s + settled);
    }).observe(document, {
      subtree: true,
      childList: true,
      attributes: true,
      attributeFilter: ['data-state'],
    });
  });
  await openScene(page, '#/hemisphere?n=500');
  await statsReady(page);
  const log = await page.evaluate(() => (window as unknown as { __log: string[] }).__log);
  // first waiting (no worker yet), then, once the page has settled, the run and its result
  expect(log[0]).toBe('waiting');
  const w = log.findIndex((s) => s.startsWith('worker'));
  expect(log[w]).toBe('worker settled');
  expect(log.slice(0, w).filter((s) => s.startsWith('running'))).toEqual([]);
  expect(log.slice(w)).toContain('ready settled');
  await expect(page.getByTestId('stats-status')).toHaveText('statistics up to date');

  // a change while the page is still loading is not held back: the page itself changes its
  // address right after it first shows "waiting" (from the test's side, the page could settle
  // between seeing that state and sending the change); to 200 000 directions, which the same
  // page then grows in the 3D view in chunks (the buffers' sizes up to MAX_N are
  // tests/scenes/hemisphere/pointBuffers.test.ts)
  await page.addInitScript(() => {
    if (!location.hash.includes('n=400')) return;
    const mo = new MutationObserver(() => {
      const s = document.querySelector('[data-testid="stats-status"]')?.getAttribute('data-state');
      if (s !== 'waiting') return;
      mo.disconnect();
      // after the frame that shows it, once the page listens for address changes
      requestAnimationFrame(() => setTimeout(() => (location.hash = '#/hemisphere?n=200000')));
    });
    mo.observe(document, {
      subtree: true,
      childList: true,
      attributes: true,
      attributeFilter: ['data-state'],
    });
  });
  await page.goto('about:blank');
  await openSceneNoWait(page, '#/hemisphere?n=400');
  await waitForReadout(page, 'samples', (v) => Number(v) === 200_000, 60_000);
  await statsReady(page);
  const log2 = await page.evaluate(() => (window as unknown as { __log: string[] }).__log);
  expect(log2.find((s) => s.startsWith('running'))).toBe('running'); // before the page settled

  // the growth reaches all 200 000 points in the 3D view
  const view = page.getByTestId('hemisphere-3d');
  await view.scrollIntoViewIfNeeded();
  await expect(view).toHaveAttribute('data-status', 'ready', { timeout: 30_000 });
  await expect(page.getByTestId('shown-count')).toHaveAttribute('data-value', '200000', {
    timeout: 90_000,
  });
  // the points came from the worker in chunks that add up to n
  const grown = await page.evaluate(() =>
    performance.getEntriesByName('hemisphere-grow').map((e) => (e as PerformanceMeasure).detail as number),
  );
  expect(grown.length, 'chunks').toBeGreaterThan(1);
  expect(grown.reduce((a, x) => a + x, 0)).toBeGreaterThanOrEqual(200_000);
  await expect(view).toHaveAttribute('data-status', 'ready');
});
