import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { outOfView } from '../../src/ui/focusInView';

const band = { viewport: 720, padTop: 60, padBottom: 200 };

describe('outOfView: whether a focused element has left the band between the sticky bars', () => {
  it('in the band, partly in it, or taller than it: left where it is', () => {
    expect(outOfView({ ...band, top: 100, bottom: 140 })).toBe(false);
    expect(outOfView({ ...band, top: 40, bottom: 80 })).toBe(false); // half under the header
    expect(outOfView({ ...band, top: 500, bottom: 540 })).toBe(false); // half under the drawer
    expect(outOfView({ ...band, top: -300, bottom: 2000 })).toBe(false);
  });

  it('under the header, under the drawer, above or below the screen: brought back', () => {
    expect(outOfView({ ...band, top: 10, bottom: 60 })).toBe(true);
    expect(outOfView({ ...band, top: 520, bottom: 560 })).toBe(true);
    expect(outOfView({ ...band, top: -90, bottom: -50 })).toBe(true);
    expect(outOfView({ ...band, top: 853, bottom: 877 })).toBe(true);
  });

  it('an element with no box (not rendered) is never scrolled to', () => {
    expect(outOfView({ ...band, top: 0, bottom: 0 })).toBe(false);
    expect(outOfView({ ...band, top: Number.NaN, bottom: Number.NaN })).toBe(false);
  });

  it('property: out of view exactly when no pixel row of it is in the band', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: -3000, max: 3000 }),
        fc.integer({ min: 1, max: 500 }),
        fc.integer({ min: 0, max: 100 }),
        fc.integer({ min: 0, max: 300 }),
        (top, h, padTop, padBottom) => {
          const viewport = 800;
          const rows = Array.from({ length: h }, (_, k) => top + k + 0.5);
          const seen = rows.some((y) => y > padTop && y < viewport - padBottom);
          expect(outOfView({ top, bottom: top + h, viewport, padTop, padBottom })).toBe(!seen);
        },
      ),
      { seed: 36 },
    );
  });
});
