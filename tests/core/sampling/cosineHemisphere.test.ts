import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  cosineHemispherePdf,
  invertCosineHemisphereSample,
  invertUniformDiskConcentricSample,
  sampleCosineHemisphere,
  sampleCosineHemisphereBatch,
  sampleUniformDiskConcentric,
} from '../../../src/core/sampling/cosineHemisphere';
import { Rng } from '../../../src/core/random';
import { STRESS_PAIRS, norm3 } from './stress';

const unit = fc.double({ min: 0, max: 1, maxExcluded: true, noNaN: true });

describe('cosine hemisphere', () => {
  it('stress inputs give finite unit vectors with z ≥ 0', () => {
    const out = new Float64Array(3);
    for (const [a, b] of STRESS_PAIRS) {
      sampleCosineHemisphere(a, b, out);
      expect(out.every(Number.isFinite)).toBe(true);
      expect(out[2]).toBeGreaterThanOrEqual(0);
      expect(Math.abs(norm3(out) - 1)).toBeLessThan(1e-15);
    }
  });

  it('concentric disk map stays inside the unit disk and round-trips (property)', () => {
    const d = [0, 0];
    fc.assert(
      fc.property(unit, unit, (a, b) => {
        sampleUniformDiskConcentric(a, b, d);
        if (Math.hypot(d[0], d[1]) > 1 + 1e-15) return false;
        const [u1, u2] = invertUniformDiskConcentricSample(d[0], d[1]);
        // at the centre every (u1,u2) near (½,½) maps to ~0: the inverse is only defined up to r
        const r = Math.hypot(2 * a - 1, 2 * b - 1);
        const tol = r < 1e-9 ? 1e-8 : 1e-9;
        return Math.abs(u1 - a) < tol && Math.abs(u2 - b) < tol;
      }),
      { numRuns: 3000, seed: 5 },
    );
  });

  it('round trip invert(sample(u)) ≈ u on a grid', () => {
    const out = [0, 0, 0];
    for (let i = 0; i < 33; i++)
      for (let j = 0; j < 33; j++) {
        const a = (i + 0.37) / 33;
        const b = (j + 0.61) / 33;
        sampleCosineHemisphere(a, b, out);
        const [u1, u2] = invertCosineHemisphereSample(out[0], out[1], out[2]);
        expect(Math.abs(u1 - a)).toBeLessThan(1e-12);
        expect(Math.abs(u2 - b)).toBeLessThan(1e-12);
      }
  });

  it('pdf: cos θ/π, 0 below the horizon and for NaN', () => {
    expect(cosineHemispherePdf(1)).toBe(1 / Math.PI);
    expect(cosineHemispherePdf(0.5)).toBeCloseTo(0.5 / Math.PI, 16);
    expect(cosineHemispherePdf(-0.2)).toBe(0);
    expect(cosineHemispherePdf(Number.NaN)).toBe(0);
  });

  it('batch kernel equals the scalar sampler', () => {
    const n = 1000;
    const u = new Rng(9).fill(new Float64Array(2 * n));
    const out = sampleCosineHemisphereBatch(u, new Float64Array(3 * n), n);
    const one = new Float64Array(3);
    for (let i = 0; i < n; i++) {
      sampleCosineHemisphere(u[2 * i], u[2 * i + 1], one);
      expect([out[3 * i], out[3 * i + 1], out[3 * i + 2]]).toEqual([one[0], one[1], one[2]]);
    }
  });

  it('E[cos θ] = ∫cos²θ/π dω = 2/3 within 4σ', () => {
    const rng = new Rng(12);
    const out = [0, 0, 0];
    const n = 200000;
    let s = 0;
    let s2 = 0;
    for (let i = 0; i < n; i++) {
      sampleCosineHemisphere(rng.nextFloat(), rng.nextFloat(), out);
      s += out[2];
      s2 += out[2] * out[2];
    }
    const mean = s / n;
    const sigma = Math.sqrt((s2 / n - mean * mean) / n);
    expect(Math.abs(mean - 2 / 3)).toBeLessThan(4 * sigma);
  });
});
