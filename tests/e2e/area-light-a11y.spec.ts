/**
 * #/area-light for a reader who cannot see it, read from Chromium's accessibility tree (CDP
 * Accessibility.getFullAXTree): Q6 worked through with the keyboard alone, its numbers read from
 * the tree, and the main figure's name and description holding the live numbers and following
 * the light's tilt, announced once it settles. The description's wording for every placement is a
 * unit test (tests/scenes/area-light/describe.test.ts); the whole page's tab stops, axe, focus,
 * ask=1 and the classroom stage are in catalogue.spec.ts.
 */
import type { Page } from '@playwright/test';
import { test, expect, openScene } from './fixtures';
import { axTree } from './axTree';
import { defaultValues, parseParams } from '../../src/kit/params';
import { EXAM_PRESET, schema } from '../../src/scenes/area-light/params';
import { animationFrame, animationLength, sampleRun } from '../../src/scenes/area-light/animation';
import { buildModel, targetValue } from '../../src/scenes/area-light/model';
import { patchModel } from '../../src/scenes/area-light/patch';
import { centreView } from '../../src/scenes/area-light/view/describe';
import { formatNumber } from '../../src/ui/Readout';
import type { LightStrategy } from '../../src/core/lights';

const FIGURE = 'The area light, the shading point and the samples arriving';

/** The figure's role and description as a screen reader receives them, found by its name (null: none). */
async function axFigure(page: Page, name: string): Promise<{ role: string; description: string } | null> {
  return (await axTree(page)).find((n) => n.name === name) ?? null;
}

async function figureDescription(page: Page): Promise<string> {
  const n = await axFigure(page, FIGURE);
  expect(n, 'the main figure is in the accessibility tree by its name').not.toBeNull();
  return n!.description;
}

/** The model for a query string, computed here with the app's own parser and defaults. */
function modelFor(query: string) {
  const v = { ...defaultValues(schema), ...parseParams(schema, new URLSearchParams(query)).values };
  const m = buildModel(v);
  return { v, m, patch: patchModel(m, v.pu, v.pv, v.psize, v.ptilt) };
}

const f = (x: number, d = 4) => formatNumber(x, d).replace(/^-/, '−');

test('keyboard and accessibility tree: Q6 by keyboard alone, then the figure’s description follows the light’s tilt', async ({
  page,
}) => {
  test.setTimeout(180_000);
  await test.step('keyboard only: the exam’s configuration, a tilted patch and the numbers Q6 asks for', async () => {
    await openScene(page, '#/area-light?n=1024&seed=1');
    /** Tab until the focused element has this test id, or a label starting with this text. */
    const tabTo = async (want: { testId?: string; label?: string }, limit = 400) => {
      for (let i = 0; i < limit; i++) {
        await page.keyboard.press('Tab');
        const hit = await page.evaluate(({ testId, label }) => {
          const el = document.activeElement as HTMLInputElement | null;
          if (!el) return false;
          if (testId) return el.getAttribute('data-testid') === testId;
          return !!label && !!el.labels?.[0]?.textContent?.startsWith(label);
        }, want);
        if (hit) return;
      }
      throw new Error(`never reached by Tab: ${JSON.stringify(want)}`);
    };
    await tabTo({ testId: 'exam-config' });
    await page.keyboard.press('Enter');
    await expect(page.getByTestId('exam-config')).toHaveAttribute('aria-pressed', 'true');
    await expect.poll(() => figureDescription(page)).toContain('parallel to the floor');
    expect(await figureDescription(page)).toContain('cos θ = cos θₗ = 1;');

    // Q6(a): tilt the patch with the arrow keys; dω = dA cos θₗ / r² for it, read from the figure
    await tabTo({ label: 'Patch tilt' });
    expect(await page.evaluate(() => (document.activeElement as HTMLInputElement).type)).toBe('range');
    for (let i = 0; i < 20; i++) await page.keyboard.press('ArrowRight');
    await expect(page).toHaveURL(/ptilt=20/);
    const exam = modelFor(
      `p=0,0,0&lc=0,0,2&ls=1,1&tilt=0&pu=${EXAM_PRESET.params.pu}&pv=${EXAM_PRESET.params.pv}&psize=${EXAM_PRESET.params.psize}&ptilt=20`,
    );
    await expect
      .poll(() => figureDescription(page))
      .toContain(`dω = dA cos θₗ / r² = ${f(exam.patch.approx)} sr (exactly ${f(exam.patch.exact)} sr)`);
    expect(await figureDescription(page)).toContain(`cos θₗ = ${f(exam.patch.cosThetaL, 3)}, so dA⊥`);

    // Q6(c): the area estimator's value with all 1024 samples, and the reference it must meet
    const run = sampleRun(exam.m, 'area', 1024, 1);
    const fr = animationFrame(run, 1024);
    const d = await figureDescription(page);
    expect(d).toContain(`running estimate ${f(fr.estimate)} ± ${f(fr.stderr, 2)}`);
    expect(d).toContain(`reference ${f(targetValue(exam.m))}`);
    expect(Math.abs(fr.estimate - targetValue(exam.m))).toBeLessThan(3 * fr.stderr);
  });

  await test.step('the opening link: the figure’s description holds the live numbers and follows the light’s tilt', async () => {
    // the light's controls are in the fold "setup", opened by the link
    await openScene(page, '#/area-light?open=setup');
    const { m, patch, v } = modelFor('');
    const cv = centreView(m);
    const run = sampleRun(m, v.strategy as LightStrategy, animationLength(v.n), v.seed);
    const fr = animationFrame(run, v.t);
    await expect
      .poll(() => figureDescription(page), { timeout: 30000 })
      .toContain('tilted 30° from the floor (tilt −30° about its x axis)');
    const d = await figureDescription(page);
    expect((await axFigure(page, FIGURE))!.role).toBe('group');
    expect(d).toContain(
      `cos θ = ${f(cv.cosTheta, 3)} at the point, cos θₗ = ${f(cv.cosThetaL, 3)} at the light`,
    );
    expect(d).toContain(`dω = dA cos θₗ / r² = ${f(patch.approx)} sr`);
    expect(d).toContain(`${fr.k} of ${run.count} arrived`);
    expect(d).toContain(`running estimate ${f(fr.estimate)} ± ${f(fr.stderr, 2)}`);
    expect(d).toContain(`reference ${f(targetValue(m))}`);

    // tilt the light by keyboard (the slider in the controls): the description follows
    const tilt = page.getByRole('slider', { name: /^Tilt about x/ });
    await tilt.focus();
    await page.keyboard.press('ArrowRight');
    await expect(page).toHaveURL(/tilt=-29/);
    await expect.poll(() => figureDescription(page)).toContain('tilted 29° from the floor');
    const after = modelFor('tilt=-29');
    expect(await figureDescription(page)).toContain(
      `cos θₗ = ${f(centreView(after.m).cosThetaL, 3)} at the light`,
    );
    // and it is announced once the input settles (the page's one live region)
    await expect(page.getByTestId('live-region')).toContainText('tilted 29° from the floor', {
      timeout: 10000,
    });
  });
});
