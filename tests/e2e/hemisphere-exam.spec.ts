/**
 * Browser tests of #/hemisphere, exam first and the warp morph on the shared timeline.
 * Expected values come from the scene's own pure model run here in Node (same core
 * code, same seed), never from the answer key.
 */
import type { Page } from '@playwright/test';
import { test, expect, openScene, readoutNumber } from './fixtures';
import { animFrame } from '../../src/scenes/hemisphere/animation';
import { computeDrawStats } from '../../src/scenes/hemisphere/drawStats';
import { makeLobe } from '../../src/scenes/hemisphere/lobe';
import { rmseOverRuns } from '../../src/scenes/hemisphere/q2Estimates';
import { examLobeK } from '../../src/core/sampling';
import { formatNumber } from '../../src/ui/Readout';

const cosTheta = (t: number) => Math.cos(t);

async function statsReady(page: Page) {
  await expect(page.getByTestId('stats-status')).toHaveAttribute('data-state', 'ready', { timeout: 30_000 });
}

/** The timeline's exact position (data-t carries String(t)). */
async function position(page: Page): Promise<number> {
  return Number(await page.getByTestId('timeline').getAttribute('data-t'));
}

/** The warp readouts equal the model's frame at t. */
async function expectFrame(page: Page, t: number, n: number, seed = 1, anim: 'warp' | 'grow' = 'warp') {
  const f = animFrame(makeLobe('exam', 8), 'independent', seed, n, anim, t);
  await expect(page.getByTestId('morph-s')).toHaveAttribute('data-value', String(f.s));
  await expect(page.getByTestId('anim-count')).toHaveAttribute('data-value', String(f.shown));
  await expect(page.getByTestId('tracked-x')).toHaveAttribute('data-value', String(f.tracked!.pos[0]));
  await expect(page.getByTestId('tracked-y')).toHaveAttribute('data-value', String(f.tracked!.pos[1]));
  await expect(page.getByTestId('tracked-z')).toHaveAttribute('data-value', String(f.tracked!.pos[2]));
  return f;
}

test.describe('exam first: Q1 and Q2 part by part', () => {
  test('parts in exam order, each with a derivation and live numbers', async ({ page }) => {
    await openScene(page, '#/hemisphere?n=2000');
    const ids = ['1a', '1b', '1c', '1d', '2a', '2b', '2c'];
    const tops: number[] = [];
    for (const id of ids) {
      const part = page.getByTestId(`part-${id}`);
      await expect(part).toBeVisible();
      await expect(part.locator('.exam-asks')).toBeVisible();
      await expect(part.locator('.exam-derivation')).toBeVisible();
      tops.push((await part.boundingBox())!.y);
    }
    expect([...tops].sort((a, b) => a - b)).toEqual(tops);
    // the explore-further section comes after the last part
    const explore = (await page.getByTestId('explore-further').boundingBox())!.y;
    expect(explore).toBeGreaterThan(tops[tops.length - 1]);

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
    // Q1b: both marginals, the paper's identity credited, the key's 2 cot θ and its divergence, the stray e^φ
    await expect(page.getByTestId('steps-1b-theta')).toContainText('sin 2');
    await expect(page.getByTestId('steps-1b-phi')).toContainText('separable');
    await expect(page.getByTestId('paper-identity')).toContainText('printed');
    await expect(page.getByTestId('paper-identity')).toContainText('leniently');
    await expect(page.getByTestId('steps-1b-paper')).toContainText('2\\cot\\theta');
    await expect(page.getByTestId('steps-1b-paper')).toContainText('not integrable');
    await expect(page.getByTestId('keynote-stray-ephi')).toContainText('outside the integral');
    await expect(page.getByTestId('keynote-stray-ephi')).toContainText('survives one more line');
    await expect(page.locator('main')).not.toContainText('see below');
    // Q1c, Q1d: CDF check at the first sample, both θ forms and the φ form with its numbers
    await expect(page.getByTestId('steps-1c-theta')).toContainText('sin^2');
    // the key's form θ = ½ cos⁻¹(1 − 2ξ₁), read in the MathML (the TeX source now groups the
    // parenthesis, {(1-2\xi_1)}, so that a phone's line break falls outside it)
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
});

test.describe('statements that must be true', () => {
  test('Phong n = 8 with f = cos θ: infinite-variance warning; the repeat summary explains the Phong lobe', async ({
    page,
  }) => {
    await openScene(page, '#/hemisphere?lobe=phong&exponent=8&n=2000');
    await statsReady(page);
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

  // one low-discrepancy set stands for the three (the page's note takes the same path for each; the
  // RMSE of every set is a unit test of the model)
  for (const kind of ['sobol'] as const) {
    test(`points=${kind}: s/√N is not shown as the error; the RMSE over randomized runs is, equal to the model's`, async ({
      page,
    }) => {
      await openScene(page, `#/hemisphere?points=${kind}&n=1024`);
      await statsReady(page);
      await expect(page.getByTestId('stderr-note')).toContainText('not an error estimate');
      const lobe = makeLobe('exam', 8)!;
      const core = computeDrawStats(lobe, cosTheta, kind, 1, 1024);
      const r = rmseOverRuns(lobe, cosTheta, kind, 1, 1024, core.exact);
      await expect(page.getByTestId('stderr-note')).toContainText(formatNumber(r.uniform, 3));
      const uniNote = page.getByTestId('answer-2a').locator('.readout-note');
      await expect(uniNote).toContainText(`RMSE ${formatNumber(r.uniform, 3)}`);
      await expect(uniNote).not.toContainText('std. error');
      await expect(page.getByTestId('answer-2b').locator('.readout-note')).toContainText(
        `RMSE ${formatNumber(r.importance, 3)}`,
      );
    });
  }
});

test.describe('the warp morph on the shared timeline', () => {
  test('play, pause: the readouts equal the model at the paused position; the link restores them', async ({
    page,
    context,
  }) => {
    await openScene(page, '#/hemisphere?n=2000&t=0');
    await expectFrame(page, 0, 2000);
    await page.getByTestId('timeline-play').click();
    await expect.poll(() => position(page), { timeout: 30_000 }).toBeGreaterThan(0.15);
    await page.getByTestId('timeline-play').click();
    await expect(page.getByTestId('timeline')).toHaveAttribute('data-playing', '0');
    const t = await position(page);
    expect(t).toBeGreaterThan(0.15);
    expect(t).toBeLessThanOrEqual(1);
    const f = await expectFrame(page, t, 2000);
    await expect(page).toHaveURL(new RegExp(`[?&]t=${String(t).replace('.', '\\.')}(&|$)`));
    const again = await context.newPage();
    await openScene(again, page.url().slice(page.url().indexOf('#')));
    await expect(again.getByTestId('timeline')).toHaveAttribute('data-t', String(t));
    await expectFrame(again, t, 2000);
    await expect(again.getByTestId('tracked-z')).toHaveAttribute('data-value', String(f.tracked!.pos[2]));
    await again.close();
  });
});

// readoutNumber is re-exported for symmetry with the other specs
void readoutNumber;
