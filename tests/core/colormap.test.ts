import { describe, expect, it } from 'vitest';
import { colorInto, colorizeInto, DIVERGING, MAGMA, VIRIDIS } from '../../src/core/colormap';

/** Relative luminance (WCAG) of an sRGB byte triple. */
function luminance(c: ArrayLike<number>): number {
  const lin = (v: number) => {
    const s = v / 255;
    return s <= 0.04045 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
  };
  return 0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2]);
}

describe('colormap', () => {
  for (const map of [VIRIDIS, MAGMA]) {
    it(`${map.name}: luminance rises monotonically from 0 to 1 (a perceptual ramp, not a rainbow)`, () => {
      let prev = -1;
      for (let k = 0; k <= 100; k++) {
        const c = [0, 0, 0];
        colorInto(k / 100, c, 0, map);
        const y = luminance(c);
        expect(y).toBeGreaterThan(prev);
        prev = y;
      }
    });
    it(`${map.name}: the batched image path gives the same bytes as the scalar one`, () => {
      const n = 37;
      const values = Float64Array.from({ length: n }, (_, i) => -3 + (i * 7.3) / n);
      const img = new Uint8ClampedArray(4 * n);
      colorizeInto(values, n, -2, 3, img, map);
      for (let k = 0; k < n; k++) {
        const c = [0, 0, 0];
        colorInto((values[k] + 2) / 5, c, 0, map);
        expect([img[4 * k], img[4 * k + 1], img[4 * k + 2], img[4 * k + 3]]).toEqual([...c, 255]);
      }
    });
  }
  it('diverging: luminance rises to its lightest at the middle and falls after it; blue below, red above', () => {
    const lum = (t: number) => {
      const c = [0, 0, 0];
      colorInto(t, c, 0, DIVERGING);
      return { y: luminance(c), c };
    };
    for (let k = 0; k < 50; k++) {
      expect(lum((k + 1) / 100).y).toBeGreaterThan(lum(k / 100).y);
      expect(lum(1 - (k + 1) / 100).y).toBeGreaterThan(lum(1 - k / 100).y);
    }
    const lo = lum(0.1).c;
    const hi = lum(0.9).c;
    expect(lo[2]).toBeGreaterThan(lo[0]);
    expect(hi[0]).toBeGreaterThan(hi[2]);
  });
  it(`diverging: the batched image path gives the same bytes as the scalar one`, () => {
    const values = Float64Array.from({ length: 21 }, (_, i) => -5 + i / 2);
    const img = new Uint8ClampedArray(4 * 21);
    colorizeInto(values, 21, -4, 4, img, DIVERGING);
    for (let k = 0; k < 21; k++) {
      const c = [0, 0, 0];
      colorInto((values[k] + 4) / 8, c, 0, DIVERGING);
      expect([img[4 * k], img[4 * k + 1], img[4 * k + 2]]).toEqual(c);
    }
  });
  it('the ends are the published stops', () => {
    const c = [0, 0, 0];
    colorInto(0, c, 0, MAGMA);
    expect(c).toEqual([0, 0, 4]);
    colorInto(1, c, 0, MAGMA);
    expect(c).toEqual([252, 253, 191]);
    colorInto(Number.NaN, c, 0, VIRIDIS);
    expect(c).toEqual([68, 1, 84]);
  });
});
