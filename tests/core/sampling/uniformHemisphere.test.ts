import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  invertUniformHemisphereSample,
  sampleUniformHemisphere,
  sampleUniformHemisphereBatch,
  uniformHemispherePdf,
} from '../../../src/core/sampling/uniformHemisphere';
import { Rng } from '../../../src/core/random';
import { STRESS_PAIRS, norm3, torusDist } from './stress';

const unit = fc.double({ min: 0, max: 1, maxExcluded: true, noNaN: true });

describe('uniform hemisphere', () => {
  it('stress inputs give finite unit vectors in the upper hemisphere', () => {
    const out = new Float64Array(3);
    for (const [a, b] of STRESS_PAIRS) {
      sampleUniformHemisphere(a, b, out);
      expect(out.every(Number.isFinite)).toBe(true);
      expect(out[2]).toBeGreaterThanOrEqual(0);
      expect(Math.abs(norm3(out) - 1)).toBeLessThan(1e-15);
      expect(uniformHemispherePdf(out[2])).toBeCloseTo(1 / (2 * Math.PI), 15);
    }
  });

  it('round trip invert(sample(u)) ≈ u over the whole square (property)', () => {
    const out = [0, 0, 0];
    fc.assert(
      fc.property(unit, unit, (a, b) => {
        sampleUniformHemisphere(a, b, out);
        const [u1, u2] = invertUniformHemisphereSample(out[0], out[1], out[2]);
        // near the pole the azimuth is undefined: only check u2 where sin θ is not tiny
        const ok1 = Math.abs(u1 - a) < 1e-12;
        const ok2 = a > 1 - 1e-8 || torusDist(u2, b) < 1e-9;
        return ok1 && ok2;
      }),
      { numRuns: 2000, seed: 7 },
    );
  });

  it('pdf is 0 below the horizon and for NaN, constant above', () => {
    expect(uniformHemispherePdf(-1e-300)).toBe(0);
    expect(uniformHemispherePdf(-1)).toBe(0);
    expect(uniformHemispherePdf(Number.NaN)).toBe(0);
    expect(uniformHemispherePdf(0.3)).toBe(1 / (2 * Math.PI));
  });

  it('batch kernel equals the scalar sampler bit for bit', () => {
    const n = 1000;
    const u = new Rng(3).fill(new Float64Array(2 * n));
    const out = sampleUniformHemisphereBatch(u, new Float64Array(3 * n), n);
    const one = new Float64Array(3);
    for (let i = 0; i < n; i++) {
      sampleUniformHemisphere(u[2 * i], u[2 * i + 1], one);
      expect([out[3 * i], out[3 * i + 1], out[3 * i + 2]]).toEqual([one[0], one[1], one[2]]);
    }
  });

  it('mean of cos θ is ½ (∫ cos θ dω / 2π), within 4σ', () => {
    const rng = new Rng(11);
    const out = [0, 0, 0];
    let s = 0;
    const n = 200000;
    for (let i = 0; i < n; i++) {
      sampleUniformHemisphere(rng.nextFloat(), rng.nextFloat(), out);
      s += out[2];
    }
    const sigma = Math.sqrt(1 / 12 / n);
    expect(Math.abs(s / n - 0.5)).toBeLessThan(4 * sigma);
  });
});
