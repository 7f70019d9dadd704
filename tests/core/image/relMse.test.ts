import { describe, expect, it } from 'vitest';
import { REL_MSE_EPSILON, relMse, relMseRgba8 } from '../../../src/core/image/relMse';
import { srgbToLinear } from '../../../src/core/image/flip';
import { meanVariance, stdDevImage } from '../../../src/core/image/stdDevImage';
import { Rng } from '../../../src/core/random/rng';

describe('relMse', () => {
  it('is the mean of (x − ref)²/(ref² + 0.01), computed by hand', () => {
    expect(REL_MSE_EPSILON).toBe(0.01);
    // (1.1 − 1)²/(1 + 0.01) and (0.1 − 0)²/(0 + 0.01) = 1
    expect(relMse([1.1, 0.1], [1, 0])).toBeCloseTo((0.01 / 1.01 + 1) / 2, 15);
    expect(relMse([2, 3], [2, 3])).toBe(0);
    expect(relMse([2], [1], 0)).toBe(1);
  });
  it('skips pairs that are not finite and refuses different sizes', () => {
    expect(relMse([NaN, 1.5, 4], [1, 1, Infinity])).toBeCloseTo(0.25 / 1.01, 15);
    expect(relMse([NaN], [1])).toBeNaN();
    expect(() => relMse([1, 2], [1])).toThrow(RangeError);
  });
});

describe('relMseRgba8', () => {
  it('compares the linear RGB of 8-bit sRGB pixels, ignoring alpha', () => {
    const ref = [255, 0, 128, 255];
    const test = [255, 10, 128, 0];
    const d = srgbToLinear(10 / 255);
    // three channels: 0, d²/(0 + ε), 0
    expect(relMseRgba8(test, ref)).toBeCloseTo((d * d) / 0.01 / 3, 15);
    expect(relMseRgba8(ref, ref)).toBe(0);
    expect(() => relMseRgba8([1, 2, 3, 4], [1])).toThrow(RangeError);
  });
});

describe('stdDevImage', () => {
  it('gives the sample standard deviation per pixel', () => {
    const sd = stdDevImage([
      [1, 5, 0],
      [3, 5, 0],
      [5, 5, 3],
    ]);
    expect(sd[0]).toBeCloseTo(2, 15); // values 1, 3, 5: s² = (4 + 0 + 4)/2
    expect(sd[1]).toBe(0);
    expect(sd[2]).toBeCloseTo(Math.sqrt(3), 15); // 0, 0, 3: mean 1, s² = (1 + 1 + 4)/2
    expect(meanVariance(sd)).toBeCloseTo((4 + 0 + 3) / 3, 14);
  });
  it('recovers the noise of K independent runs: mean variance near σ² = 1/12 for uniforms', () => {
    const rng = new Rng(11);
    const runs = Array.from({ length: 16 }, () => Float64Array.from({ length: 4000 }, () => rng.nextFloat()));
    const v = meanVariance(stdDevImage(runs));
    // the mean of 4000 unbiased s² (15 dof each): sd of the mean ≈ (1/12)·√(2/15)/√4000 ≈ 4.8e-4
    expect(Math.abs(v - 1 / 12)).toBeLessThan(2.5e-3);
  });
  it('needs two runs of one size', () => {
    expect(() => stdDevImage([[1, 2]])).toThrow(RangeError);
    expect(() => stdDevImage([[1, 2], [1]])).toThrow(RangeError);
  });
});
