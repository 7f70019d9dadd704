/**
 * The float32 sums of the GPU's accumulation target, emulated with Math.fround: Kahan's
 * compensated sum keeps the digits the naive sum loses, over 2²⁰ terms by orders of magnitude, as
 * Higham's bounds say; and the image's naive-sum error from the target's channels.
 */
import { describe, expect, it } from 'vitest';
import {
  F32_UNIT_ROUNDOFF,
  addF32,
  naiveSumBound,
  naiveSumError,
  newF32Sums,
  sumF32,
} from '../../../src/core/render/f32Sum';
import { Rng } from '../../../src/core/random/rng';

describe('float32 naive and Kahan sums', () => {
  it('agree with the exact sum while every partial sum is exact', () => {
    const s = sumF32([1, 2, 0.5, 0.25]);
    expect(s).toEqual({ naive: 3.75, kahan: 3.75, comp: 0 });
  });

  it('rounds like float32: 2²⁴ + 1 is lost by the naive sum and kept by Kahan’s', () => {
    const s = newF32Sums();
    addF32(s, 2 ** 24);
    addF32(s, 1);
    addF32(s, 1);
    expect(s.naive).toBe(2 ** 24);
    expect(s.kahan).toBe(2 ** 24 + 2);
  });

  it('over 2²⁰ terms Kahan beats the naive sum, each within its bound', () => {
    const n = 2 ** 20;
    const rng = new Rng(7, 0);
    const xs = new Float32Array(n);
    for (let k = 0; k < n; k++) xs[k] = rng.nextFloat();
    let exact = 0;
    for (const x of xs) exact += x; // float64: exact to about 2⁻³³ relative here
    const s = sumF32(xs);
    const naive = Math.abs(s.naive - exact) / exact;
    const kahan = Math.abs(s.kahan - exact) / exact;
    expect(naive).toBeGreaterThan(1e-6);
    expect(naive).toBeLessThanOrEqual(naiveSumBound(n, F32_UNIT_ROUNDOFF));
    expect(kahan).toBeLessThanOrEqual(2 * F32_UNIT_ROUNDOFF);
    expect(naive / Math.max(kahan, 2 ** -40)).toBeGreaterThan(100);
  });

  it('measures an image’s naive error from its RGBA sums, skipping empty pixels', () => {
    const rgba = Float32Array.of(1.5, 1.25, 0, 0, 0, 0, 0, 0, 2, 2, 0, 0);
    expect(naiveSumError(rgba)).toBeCloseTo((0.25 / 1.25 + 0) / 2, 12);
    expect(naiveSumError(new Float32Array(8))).toBeNaN();
  });

  it('bounds the naive sum by (n − 1)u / (1 − (n − 1)u)', () => {
    expect(naiveSumBound(1, 0.1)).toBe(0);
    expect(naiveSumBound(3, 0.1)).toBeCloseTo(0.25, 12);
    expect(naiveSumBound(20, 0.1)).toBe(Infinity);
  });
});
