// #/hemisphere: the exam's warps in float32, and 10⁶ directions from a WebGL2 vertex shader
// (SwiftShader in headless Chromium), read back and χ²-tested against the exam's pdf in the
// scene's worker once the canvas is on screen (the check itself: tests/scenes/hemisphere/gpuCheck).
// The panel with its results is scanned by axe here: the whole-page pass opens the fold but does
// not scroll to the canvas, so no shader runs there.
import { test, expect, openScene, readout } from './fixtures';
import { axeViolations } from './wholePage';

test('10⁶ GPU directions pass the χ² test against the exam pdf (both forms)', async ({ page }) => {
  test.setTimeout(180_000);
  await openScene(page, '#/hemisphere?seed=7');
  const details = page.getByTestId('gpu-warp-details');
  await details.scrollIntoViewIfNeeded();
  await expect(page.getByTestId('gpu-warp-panel')).toHaveCount(0);
  await details.locator('summary').click();
  await expect(page.getByTestId('warp-f32-table')).toBeVisible({ timeout: 30_000 });
  await expect(page.getByTestId('gpu-warp-unavailable')).toHaveCount(0);
  // (the shader runs once its canvas comes on screen)
  await page.getByTestId('gpu-warp-canvas').scrollIntoViewIfNeeded();
  const threshold = Number(await readout(page, 'gpu-chi2-threshold'));
  expect(threshold).toBeCloseTo(1 - Math.sqrt(0.99), 10);
  for (const form of [1, 0]) {
    await page.getByTestId(`gpu-warp-form-${form}`).check();
    await expect(page.getByTestId('gpu-chi2-pass')).toHaveAttribute('data-value', /^(yes|no)$/, {
      timeout: 90_000,
    });
    const p = Number(await readout(page, 'gpu-chi2-p'));
    expect(p, `form ${form}: p-value above the Šidák threshold`).toBeGreaterThan(threshold);
    await expect(page.getByTestId('gpu-chi2-pass')).toHaveAttribute('data-value', 'yes');
    // the GPU's directions are the emulation's to well below the χ² bins' resolution (its sin
    // and cos are approximations: SwiftShader's are off by about 2·10⁻⁴)
    const diff = Number(await readout(page, 'gpu-warp-max-diff'));
    expect(diff).toBeLessThan(1e-3);
  }
  // the canvas shows the points (not just the clear colour)
  const lit = await page.getByTestId('gpu-warp-canvas').evaluate((cv: HTMLCanvasElement) => {
    const g = document.createElement('canvas');
    g.width = cv.width;
    g.height = cv.height;
    const c = g.getContext('2d')!;
    c.drawImage(cv, 0, 0);
    const d = c.getImageData(0, 0, g.width, g.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] > 60) n++;
    return n;
  });
  expect(lit).toBeGreaterThan(1000);
  // the panel with its results, as a reader meets it
  expect(await axeViolations(page, 'GPU panel', { include: '[data-testid="gpu-warp-panel"]' })).toEqual([]);
});
