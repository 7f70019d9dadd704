/**
 * Layout of #/texture's "The whole texture, reconstructed" (the fold `whole`): each reconstruction's canvas and the
 * SVG overlay with the query's cross share one box, so the cross lands on the picture at the
 * query's texel, and the two pictures stay side by side inside their card, on a laptop and on a
 * phone.
 */
import type { Page } from '@playwright/test';
import { test, expect, openScene } from './fixtures';

/** The exam's query (the scene's default), in the texture frame: u right, v up. */
const U = 0.4;
const V = 0.24;

interface Box {
  x: number;
  y: number;
  width: number;
  height: number;
}

/** The boxes of both reconstructions (canvas and query cross) and of the card that holds them. */
async function reconBoxes(page: Page): Promise<{ card: Box; figs: { canvas: Box; cross: Box }[] }> {
  const recon = page.locator('.tx-recon');
  await recon.scrollIntoViewIfNeeded();
  return recon.evaluate((el) => {
    const box = (e: Element | null): Box => {
      if (!e) throw new Error('missing element');
      const r = e.getBoundingClientRect();
      return { x: r.left, y: r.top, width: r.width, height: r.height };
    };
    return {
      card: box(el.closest('.panel')),
      figs: [...el.querySelectorAll('.tx-recon-box')].map((b) => ({
        canvas: box(b.querySelector('canvas')),
        cross: box(b.querySelector('.tx-query')),
      })),
    };
  });
}

const overlap = (a: Box, b: Box) =>
  a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;

for (const [w, h] of [
  [1280, 900],
  [375, 800],
] as const) {
  test(`${w} px: the query's cross sits on each picture at (u, v), and the pictures stay apart inside their card`, async ({
    page,
  }) => {
    await page.setViewportSize({ width: w, height: h });
    await openScene(page, '#/texture?open=whole');
    const { card, figs } = await reconBoxes(page);
    expect(figs).toHaveLength(2);
    for (const [k, { canvas, cross }] of figs.entries()) {
      const name = k === 0 ? 'nearest' : 'bilinear';
      expect(canvas.width, `${name} canvas has a size`).toBeGreaterThan(50);
      // the cross is symmetric about the query, so its box's centre is the query's point
      const cx = cross.x + cross.width / 2;
      const cy = cross.y + cross.height / 2;
      const ex = canvas.x + U * canvas.width;
      const ey = canvas.y + (1 - V) * canvas.height;
      expect(Math.abs(cx - ex), `${name}: cross x ${cx} vs (u) on the canvas ${ex}`).toBeLessThanOrEqual(2);
      expect(Math.abs(cy - ey), `${name}: cross y ${cy} vs (v) on the canvas ${ey}`).toBeLessThanOrEqual(2);
      // inside the card
      expect(canvas.x, `${name} canvas left of the card's edge`).toBeGreaterThanOrEqual(card.x);
      expect(canvas.x + canvas.width, `${name} canvas past the card's right edge`).toBeLessThanOrEqual(
        card.x + card.width,
      );
      expect(canvas.y, `${name} canvas above the card`).toBeGreaterThanOrEqual(card.y);
      expect(canvas.y + canvas.height, `${name} canvas below the card`).toBeLessThanOrEqual(
        card.y + card.height,
      );
    }
    expect(overlap(figs[0].canvas, figs[1].canvas), 'the two canvases overlap').toBe(false);
  });
}
