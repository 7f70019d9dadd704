/**
 * The nearest-neighbour image drawn as rectangles (the texel grid's canvas) gives exactly the
 * pixels of the image written pixel by pixel, for every convention, wrap mode and window.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { randomGrid, WRAP_MODES } from '../../../src/core/texture';
import { nearestRects, texelColours, textureImage } from '../../../src/scenes/texture/textureImage';

/** The rectangles filled into an RGBA image, each with its texel's colour; unfilled pixels stay 0. */
function paint(
  rects: NonNullable<ReturnType<typeof nearestRects>>,
  lut: Uint8ClampedArray,
  w: number,
  h: number,
) {
  const img = new Uint8ClampedArray(4 * w * h);
  const hits = new Uint8Array(w * h);
  for (const r of rects)
    for (let y = r.y; y < r.y + r.h; y++)
      for (let x = r.x; x < r.x + r.w; x++) {
        hits[y * w + x]++;
        img.set(lut.subarray(4 * r.texel, 4 * r.texel + 4), 4 * (y * w + x));
      }
  return { img, hits };
}

describe('nearestRects', () => {
  it('tiles the image once over, each pixel in its texel’s colour, as textureImage writes it', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 7 }),
        fc.integer({ min: 1, max: 7 }),
        fc.integer({ min: 1, max: 60 }),
        fc.integer({ min: 1, max: 60 }),
        fc.constantFrom('corner' as const, 'center' as const),
        fc.constantFrom(...WRAP_MODES),
        fc.boolean(),
        fc.double({ min: -1, max: 0.5, noNaN: true }),
        fc.double({ min: 0.5, max: 2, noNaN: true }),
        fc.integer({ min: 0, max: 1000 }),
        (gw, gh, w, h, align, wrap, vflip, lo, hi, seed) => {
          const grid = randomGrid(gw, gh, seed);
          const opts = { align, wrap, vflip };
          const win = { uMin: lo, uMax: hi, vMin: lo - 0.1, vMax: hi + 0.2 };
          const rects = nearestRects(grid, opts, w, h, win);
          expect(rects).not.toBeNull();
          const { img, hits } = paint(rects!, texelColours(grid), w, h);
          expect(hits.every((n) => n === 1)).toBe(true);
          expect(img).toEqual(textureImage(grid, opts, 'nearest', w, h, undefined, win));
        },
      ),
      { seed: 33, numRuns: 150 },
    );
  });

  it('the exam’s 5 × 5 grid over [0, 1]² is 25 rectangles; a grid finer than the image gives none (pixels instead)', () => {
    const grid = randomGrid(5, 5, 1);
    const opts = { align: 'center' as const, wrap: 'clamp' as const, vflip: false };
    expect(nearestRects(grid, opts, 400, 400)).toHaveLength(25);
    expect(nearestRects(randomGrid(80, 80, 2), opts, 400, 400)).toBeNull();
  });
});
