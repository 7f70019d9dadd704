/**
 * FLIP of a render as it is shown: zero for the reference itself, the same number as FLIP computed
 * directly on the displayed 8-bit levels, pixels without a reference counted as no error and left
 * out of the mean, and a larger error for a noisier image.
 */
import { describe, expect, it } from 'vitest';
import { displayFlipMean } from '../../../src/core/render/displayFlip';
import { flipErrorMap } from '../../../src/core/image/flip';
import { srgbByte } from '../../../src/core/image/srgb';
import { Rng } from '../../../src/core/random/rng';

const RES = 16;
const ramp = Float64Array.from({ length: RES * RES }, (_, k) => (k % RES) / RES);

/** `values` plus uniform noise of half-width `a`, seeded. */
function noisy(values: Float64Array, a: number, seed: number): Float64Array {
  const rng = new Rng(seed);
  return values.map((v) => v + a * (2 * rng.nextFloat() - 1));
}

describe('displayFlipMean', () => {
  it('is 0 for the reference itself', () => {
    expect(displayFlipMean(ramp, ramp, RES)).toBe(0);
  });

  it('is the mean of FLIP over the displayed 8-bit levels', () => {
    const test = noisy(ramp, 0.1, 7);
    const grey = (v: Float64Array) => {
      const data = new Float64Array(3 * v.length);
      v.forEach((x, k) => data.fill(srgbByte(x) / 255, 3 * k, 3 * k + 3));
      return { width: RES, height: RES, data };
    };
    const map = flipErrorMap(grey(ramp), grey(test));
    const mean = map.reduce((a, b) => a + b, 0) / map.length;
    expect(displayFlipMean(test, ramp, RES)).toBeCloseTo(mean, 12);
  });

  it('counts a pixel without a reference as no error and leaves it out of the mean', () => {
    const test = noisy(ramp, 0.1, 3);
    const ref = Float64Array.from(ramp);
    for (let k = 0; k < RES; k++) ref[k] = NaN; // the first row has no reference
    const substituted = Float64Array.from(ramp);
    for (let k = 0; k < RES; k++) substituted[k] = test[k];
    const all = displayFlipMean(test, substituted, RES); // over all RES² pixels, the first row 0-ish
    const f = displayFlipMean(test, ref, RES);
    expect(f).toBeGreaterThan(0);
    // the same error map, averaged over the RES² − RES pixels that have a reference
    expect(f).toBeGreaterThanOrEqual(all);
    expect(Number.isNaN(displayFlipMean(test, new Float64Array(RES * RES).fill(NaN), RES))).toBe(true);
  });

  it('grows with the noise', () => {
    const a = displayFlipMean(noisy(ramp, 0.02, 1), ramp, RES);
    const b = displayFlipMean(noisy(ramp, 0.2, 1), ramp, RES);
    expect(a).toBeGreaterThan(0);
    expect(b).toBeGreaterThan(a);
  });
});
