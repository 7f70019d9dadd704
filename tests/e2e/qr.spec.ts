/**
 * The QR code beside Copy link: the pixels on screen decode (with jsQR, an independent decoder) to
 * exactly the link Copy link gives; it is large in classroom mode; its library loads only on demand.
 */
import { createRequire } from 'node:module';
import type jsQR from 'jsqr';
import type { Locator, Page } from '@playwright/test';
import { test, expect, openScene } from './fixtures';

// The decoder below is test tooling added to the page as a script, and reads the screenshot through a
// data: URL; the app's Content-Security-Policy refuses both (as it should), so this file bypasses it.
test.use({ bypassCSP: true });

const require = createRequire(import.meta.url);
const JSQR_UMD = require.resolve('jsqr/dist/jsQR.js');

/**
 * Screenshot the element (the pixels really on screen) and decode the PNG with jsQR inside the
 * page (its UMD build, added as a script), so only the decoded text travels back.
 */
async function decode(page: Page, el: Locator): Promise<string | null> {
  const png = (await el.screenshot()).toString('base64');
  if (!(await page.evaluate(() => 'jsQR' in window))) await page.addScriptTag({ path: JSQR_UMD });
  return page.evaluate(async (b64) => {
    const bmp = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
    const c = new OffscreenCanvas(bmp.width, bmp.height);
    const g = c.getContext('2d')!;
    g.drawImage(bmp, 0, 0);
    const px = g.getImageData(0, 0, bmp.width, bmp.height);
    const decoder = (window as unknown as { jsQR: typeof jsQR }).jsQR;
    return decoder(px.data, px.width, px.height)?.data ?? null;
  }, png);
}

test('the QR code decodes to the current link and follows changes; in classroom mode it is large and decodes to the room’s link', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await openScene(page, '#/texture?u=0.7&v=0.3&wrap=repeat');
  const libRequests: string[] = [];
  page.on('request', (r) => /browser-.*\.js|qrcode/.test(r.url()) && libRequests.push(r.url()));
  await page.getByTestId('copy-link').click();
  const link = await page.getByTestId('share-text').inputValue();
  expect(libRequests, 'the QR library is not loaded before it is asked for').toEqual([]);

  await page.getByTestId('show-qr').click();
  const qr = page.getByTestId('qr-code');
  await expect(qr).toBeVisible();
  expect(await decode(page, qr)).toBe(link);

  // change the scene: the code follows the new link
  await page.getByTestId('u-slider').focus();
  await page.keyboard.press('ArrowRight');
  await expect(page).not.toHaveURL(/u=0\.7(&|$)/);
  await page.getByTestId('copy-link').click();
  const link2 = await page.getByTestId('share-text').inputValue();
  expect(link2).not.toBe(link);
  await expect(qr).toHaveAttribute('data-text', link2);
  expect(await decode(page, qr)).toBe(link2);

  // Escape closes it and gives focus back to the button
  await page.keyboard.press('Escape');
  await expect(page.getByTestId('qr-panel')).toHaveCount(0);
  await expect(page.getByTestId('show-qr')).toBeFocused();

  // in classroom mode the QR code is large, and decodes to the room's link, present=1 kept
  await page.setViewportSize({ width: 1280, height: 720 });
  await openScene(page, '#/texture?present=1&u=0.2');
  await page.getByTestId('show-qr').click();
  await expect(qr).toBeVisible();
  const box = (await qr.boundingBox())!;
  expect(box.width).toBeGreaterThan(0.7 * 720);
  // the lecturer's room: students scanning it see what the projector shows
  expect(await decode(page, qr)).toMatch(/#\/texture\?(?=.*u=0\.2)(?=.*present=1)/);
  await expect(page.getByTestId('qr-keep-classroom')).toHaveCount(0);
});
