import { describe, expect, it } from 'vitest';
import { flipOfRgba8, magmaErrorImage } from '../../../src/core/image/flipRgba8';
import { flipErrorMap } from '../../../src/core/image/flip';
import { rgbFromRgba8 } from '../../../src/core/image/png';
import { MAGMA } from '../../../src/core/colormap';

describe('flipOfRgba8', () => {
  it('is FLIP of the bytes read as a PNG reader reads them (alpha dropped)', () => {
    const w = 6;
    const ref = new Uint8ClampedArray(4 * w * w).fill(200);
    const test = ref.slice();
    for (let i = 0; i < w * w; i += 5) test[4 * i + 1] = 40;
    test[3] = 0; // alpha plays no part
    const m = flipOfRgba8({ width: w, height: w, data: ref }, { width: w, height: w, data: test });
    const direct = flipErrorMap(
      rgbFromRgba8({ width: w, height: w, data: ref }),
      rgbFromRgba8({ width: w, height: w, data: test }),
    );
    expect([...m.map]).toEqual([...direct]);
    expect(m.pooled.mean).toBeGreaterThan(0);
    expect(
      flipOfRgba8({ width: w, height: w, data: ref }, { width: w, height: w, data: ref }).pooled.max,
    ).toBe(0);
  });
});

describe('magmaErrorImage', () => {
  it('colours 0 as magma’s first stop and 1 as its last, opaque', () => {
    const img = magmaErrorImage([0, 1], 2, 1);
    expect([...img.data.slice(0, 3)]).toEqual(MAGMA.stops[0].map((c) => Math.round(c)));
    expect([...img.data.slice(4, 7)]).toEqual(MAGMA.stops[MAGMA.stops.length - 1].map((c) => Math.round(c)));
    expect(img.data[3]).toBe(255);
    expect(img.data[7]).toBe(255);
  });
});
