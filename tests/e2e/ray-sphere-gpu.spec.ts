// #/ray-sphere in float32: the precision switch (every readout from the float32 emulation), and
// the WebGL2 shader (SwiftShader in headless Chromium) against the emulation and the reference.
import { test, expect, openScene, readout } from './fixtures';

const fr = Math.fround;

test('precision=f32: the readouts are float32, the textbook test fails 10⁴ r away', async ({ page }) => {
  // f = (−10⁴, −0.5, 0): in float32 c = 10⁸ − 0.75 rounds to 10⁸ and b² − 4ac = 0
  await openScene(
    page,
    '#/ray-sphere?o=0,0,0&d=1,0,0&c=10000,0.5,0&r=1&method=naive&precision=f32&open=more',
  );
  expect(await readout(page, 'c')).toBe('100000000');
  expect(await readout(page, 'discriminant')).toBe('0');
  expect(await readout(page, 'case')).toBe('tangent');
  await expect(page.getByTestId('precision-note')).toBeVisible();
  await expect(page.getByTestId('method-wrong')).toContainText('two-hits');
  // the robust form in float32 gets it right; t₀ is a float32 value
  await page.getByTestId('method').selectOption('stable');
  await expect(page).not.toHaveURL(/method=/);
  await expect.poll(() => readout(page, 'case')).toBe('two-hits');
  expect(await readout(page, 'discriminant')).toBe('3');
  const t0 = Number(await readout(page, 't0'));
  expect(fr(t0)).toBe(t0);
  expect(Math.abs(t0 - (1e4 - Math.sqrt(0.75)))).toBeLessThan(2e-3);
  // switching back to float64: the same link without precision, double results
  await page.getByTestId('precision').selectOption('f64');
  await expect(page).not.toHaveURL(/precision=/);
  await expect.poll(() => readout(page, 'c')).toBe(String(1e8 - 0.75));
});

test('the WebGL2 shader: matches the emulation; at 10⁴ r the textbook image has holes, the robust none', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await openScene(page, '#/ray-sphere');
  const details = page.getByTestId('gpu-details');
  await details.scrollIntoViewIfNeeded();
  // nothing of the panel exists until the disclosure is opened
  await expect(page.getByTestId('gpu-panel')).toHaveCount(0);
  await details.locator('summary').click();
  const panel = page.getByTestId('gpu-panel');
  await expect(panel).toBeVisible({ timeout: 30_000 });
  // SwiftShader offers WebGL2: the shader ran (no "no WebGL2" notice)
  await expect(page.getByTestId('gpu-unavailable')).toHaveCount(0);
  await expect(page.getByTestId('gpu-renderer')).not.toBeEmpty();
  const num = async (id: string) => Number(await readout(page, id));
  // at 10³ r (the opening distance) shader and emulation agree within 2 ulps on all but a few pixels
  expect(await num('image-shader-mismatch')).toBeLessThanOrEqual(0.01 * 96 * 96);
  await page.getByTestId('gpu-preset-far').click();
  await expect(panel).toHaveAttribute('data-dist', '10000');
  expect(await num('image-wrong-naive')).toBeGreaterThan(100);
  expect(await num('image-wrong-stable')).toBe(0);
  expect(await num('image-shader-mismatch')).toBeLessThanOrEqual(0.01 * 96 * 96);
  expect(await num('image-max-ulps-stable')).toBeLessThan(8);
  // the emulation agrees with the shader about the holes
  expect(await num('emu-wrong-stable')).toBe(0);
  expect(await num('emu-wrong-naive')).toBeGreaterThan(100);
});

test('without WebGL2 the panel says so and shows the emulation', async ({ page }) => {
  await page.addInitScript(() => {
    const orig = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (
      this: HTMLCanvasElement,
      kind: string,
      ...rest: unknown[]
    ) {
      if (kind === 'webgl2') return null;
      return (orig as (...a: unknown[]) => unknown).call(this, kind, ...rest);
    } as typeof orig;
  });
  await openScene(page, '#/ray-sphere');
  const details = page.getByTestId('gpu-details');
  await details.scrollIntoViewIfNeeded();
  await details.locator('summary').click();
  await expect(page.getByTestId('gpu-unavailable')).toContainText('no WebGL2');
  await page.getByTestId('gpu-preset-far').click();
  expect(Number(await readout(page, 'image-wrong-naive'))).toBeGreaterThan(100);
  expect(await readout(page, 'image-shader-mismatch')).toBe('none');
});

test('shadow acne in float32: self-hits at a small ε, none with pbrt’s offset', async ({ page }) => {
  test.setTimeout(120_000);
  await openScene(page, '#/ray-sphere');
  const details = page.getByTestId('gpu-details');
  await details.scrollIntoViewIfNeeded();
  await details.locator('summary').click();
  const acne = page.getByTestId('acne-panel');
  await acne.scrollIntoViewIfNeeded();
  await page.getByTestId('acne-dist-10000').click();
  await expect.poll(async () => Number(await readout(page, 'acne-fraction'))).toBeGreaterThan(0.1);
  await page.getByTestId('acne-pbrt').check();
  await expect.poll(async () => Number(await readout(page, 'acne-fraction'))).toBe(0);
  expect(Number(await readout(page, 'acne-lit'))).toBeGreaterThan(1000);
  // the ε needed grows with the distance; pbrt's offset never self-hits
  await expect(page.getByTestId('acne-table')).toBeVisible({ timeout: 30_000 });
  const need = async (D: number) =>
    Number(await page.getByTestId(`acne-need-${D}`).getAttribute('data-value'));
  expect(await need(1e4)).toBeGreaterThan(10 * (await need(10)));
  for (const D of [10, 100, 1000, 10000])
    await expect(page.getByTestId(`acne-pbrt-hits-${D}`)).toHaveAttribute('data-value', '0');
});
