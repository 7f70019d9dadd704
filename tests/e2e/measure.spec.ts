/**
 * The FLIP the area-light page shows is the FLIP of the two PNGs it downloads: download the render
 * and the reference, decode them here with the app's PNG reader, compute LDR-FLIP in Node and
 * compare with the `flip-mean` readout.
 */
import type { Download } from '@playwright/test';
import { test, expect, openScene, waitForReadout } from './fixtures';
import { decodePng, rgbFromRgba8 } from '../../src/core/image/png';
import { flipErrorMap } from '../../src/core/image/flip';
import { poolError } from '../../src/core/image/pooling';

async function bytesOf(d: Download): Promise<Uint8Array> {
  const chunks: Buffer[] = [];
  for await (const c of await d.createReadStream()) chunks.push(c as Buffer);
  return new Uint8Array(Buffer.concat(chunks));
}

test('area-light: flip-mean equals the FLIP of the downloaded render and reference', async ({ page }) => {
  // no animation: the timeline stands at its end, so the floor images show all 64 samples per pixel
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await openScene(page, '#/area-light?n=256&seed=4&strategy=area&open=floor');
  await page.locator('.al-images').scrollIntoViewIfNeeded();
  await expect(page.getByTestId('floor-spp')).toHaveAttribute('data-value', '64', { timeout: 30000 });
  await page.getByTestId('measure-details').locator('summary').click();
  await page.getByTestId('measure-image').selectOption('cosine');
  const shown = Number(await waitForReadout(page, 'flip-mean', (v) => v !== 'none' && v !== ''));
  await expect(page.getByTestId('measure-error-map')).toHaveAccessibleName(/FLIP error map, magma: mean/);

  const render = page.waitForEvent('download');
  await page.getByTestId('download-render').click();
  const r = await render;
  expect(r.suggestedFilename()).toMatch(/^area-light-floor-64spp-cosine-render\.png$/);
  const reference = page.waitForEvent('download');
  await page.getByTestId('download-reference').click();
  const ref = decodePng(await bytesOf(await reference));
  const test = decodePng(await bytesOf(r));
  expect([ref.width, ref.height]).toEqual([72, 72]);
  const mean = poolError(flipErrorMap(rgbFromRgba8(ref), rgbFromRgba8(test))).mean;
  expect(mean).toBeGreaterThan(0);
  expect(Math.abs(mean - shown)).toBeLessThanOrEqual(0.002);
});
