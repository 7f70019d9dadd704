import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  DensityError,
  PiecewiseConstant1D,
  validateDensity,
  densityErrorMessage,
  findInterval,
} from '../../../src/core/sampling';
import { Rng } from '../../../src/core/random';
import { chi2Test } from '../../../src/core/verify';

const STRESS = [0, 2 ** -53, 0.5, 1 - 2 ** -53];

describe('validateDensity', () => {
  it('reports negative, non-finite and all-zero tables with the first offending index', () => {
    expect(validateDensity([1, 2, 3])).toEqual({ ok: true });
    expect(validateDensity([1, -2, -3])).toEqual({ ok: false, reason: 'negative', index: 1 });
    expect(validateDensity([1, 2, Infinity])).toEqual({ ok: false, reason: 'nonfinite', index: 2 });
    expect(validateDensity([NaN])).toEqual({ ok: false, reason: 'nonfinite', index: 0 });
    expect(validateDensity([0, 0])).toEqual({ ok: false, reason: 'zero', index: -1 });
    expect(densityErrorMessage({ ok: false, reason: 'negative', index: 4 })).toMatch(
      /negative at table entry 4/,
    );
  });
  it('the constructor throws a DensityError naming the reason', () => {
    expect(() => new PiecewiseConstant1D([1, -1], 0, 1)).toThrow(DensityError);
    expect(() => new PiecewiseConstant1D([0, 0], 0, 1)).toThrow(/zero everywhere/);
    expect(() => new PiecewiseConstant1D([1, NaN], 0, 1)).toThrow(/not finite/);
    expect(() => new PiecewiseConstant1D([1], 1, 1)).toThrow(RangeError);
    expect(() => new PiecewiseConstant1D([], 0, 1)).toThrow(RangeError);
    const huge = new PiecewiseConstant1D([1e308, 1e308], 0, 10);
    expect(huge.pdf(3)).toBeCloseTo(0.1, 15);
    expect(new PiecewiseConstant1D([5e-324], 0, 1e-3).pdf(5e-4)).toBeCloseTo(1000, 10);
  });
});

describe('findInterval', () => {
  it('returns the largest index whose predicate holds, clamped to [0, size − 2]', () => {
    const cdf = [0, 0.1, 0.1, 0.5, 1];
    expect(findInterval(cdf.length, (i) => cdf[i] <= 0)).toBe(0);
    expect(findInterval(cdf.length, (i) => cdf[i] <= 0.1)).toBe(2);
    expect(findInterval(cdf.length, (i) => cdf[i] <= 0.7)).toBe(3);
    expect(findInterval(cdf.length, (i) => cdf[i] <= 1)).toBe(3);
  });
});

describe('PiecewiseConstant1D', () => {
  const f = [1, 0, 3, 2, 0, 4];
  const d = new PiecewiseConstant1D(f, -1, 2);

  it('has the right integral, CDF and a pdf that integrates to 1', () => {
    expect(d.count).toBe(6);
    expect(d.integral).toBeCloseTo(10 * 0.5, 14);
    expect(d.cdfAt(0)).toBe(0);
    expect(d.cdfAt(6)).toBe(1);
    expect(d.cdfAt(3)).toBeCloseTo(0.4, 14);
    let s = 0;
    for (let i = 0; i < 6; i++) s += d.pdf(-1 + 0.5 * (i + 0.5)) * 0.5;
    expect(s).toBeCloseTo(1, 14);
    expect(d.pdf(-1.0001)).toBe(0);
    expect(d.pdf(2.0001)).toBe(0);
    expect(d.pdf(NaN)).toBe(0);
  });

  it('samples stay in range with a positive pdf for stress ξ and never land in empty bins', () => {
    for (const u of STRESS) {
      const s = d.sample(u);
      expect(s.x).toBeGreaterThanOrEqual(-1);
      expect(s.x).toBeLessThanOrEqual(2);
      expect(s.pdf).toBeGreaterThan(0);
      expect(f[s.offset]).toBeGreaterThan(0);
      expect(s.pdf).toBe(d.pdf(s.x));
    }
    // trailing empty bins: u just below 1 must not select them
    const t = new PiecewiseConstant1D([0.1, 0.7, 0.2, 0, 0], 0, 1);
    expect(t.sample(1 - 2 ** -53).offset).toBe(2);
    expect(new PiecewiseConstant1D([0, 0, 1], 0, 1).sample(0).offset).toBe(2);
  });

  it('invert(sample(u)) = u (property, round trip)', () => {
    fc.assert(
      fc.property(fc.double({ min: 0, max: 1 - 2 ** -53, noNaN: true }), (u) => {
        const s = d.sample(u);
        return Math.abs(d.invert(s.x) - u) <= 1e-12;
      }),
    );
    for (const u of STRESS) expect(Math.abs(d.invert(d.sample(u).x) - u)).toBeLessThanOrEqual(1e-15);
  });

  it('sample(invert(x)) = x inside non-empty bins, and invert clamps outside', () => {
    for (let k = 0; k <= 300; k++) {
      const x = -1 + (3 * k) / 300;
      if (d.pdf(x) === 0 || x >= 2) continue;
      expect(d.sample(d.invert(x)).x).toBeCloseTo(x, 12);
    }
    expect(d.invert(-5)).toBe(0);
    expect(d.invert(5)).toBe(1);
    expect(d.invert(NaN)).toBe(0);
  });

  it('sampleMany matches sample exactly', () => {
    const rng = new Rng(3);
    const u = rng.fill(new Float64Array(1000));
    u.set(STRESS, 0);
    const x = new Float64Array(1000);
    const p = new Float64Array(1000);
    d.sampleMany(u, x, p);
    for (let i = 0; i < 1000; i++) {
      const s = d.sample(u[i]);
      expect(x[i]).toBe(s.x);
      expect(p[i]).toBe(s.pdf);
    }
  });

  it('samples follow the table (χ² on the bins; a wrong table is rejected)', () => {
    const rng = new Rng(11);
    const n = 60000;
    const obs = new Float64Array(6);
    for (let i = 0; i < n; i++) obs[d.sample(rng.nextFloat()).offset]++;
    const expected = f.map((v) => (n * v) / 10);
    expect(chi2Test(obs, expected).pass).toBe(true);
    const wrong = [2, 0, 3, 2, 0, 3].map((v) => (n * v) / 10);
    expect(chi2Test(obs, wrong).pass).toBe(false);
  });

  it('pdf integrates to 1 and the CDF is monotone for any valid table (property)', () => {
    fc.assert(
      fc.property(
        fc.array(fc.double({ min: 0, max: 1e6, noNaN: true }), { minLength: 1, maxLength: 50 }),
        fc.double({ min: -100, max: 100, noNaN: true }),
        fc.double({ min: 1e-3, max: 100, noNaN: true }),
        (vals, a, w) => {
          if (!vals.some((v) => v > 0)) return true;
          const t = new PiecewiseConstant1D(vals, a, a + w);
          let s = 0;
          for (let i = 0; i < t.count; i++) s += t.pdf(a + (w * (i + 0.5)) / t.count) * (w / t.count);
          for (let i = 1; i <= t.count; i++) if (t.cdfAt(i) < t.cdfAt(i - 1)) return false;
          return Math.abs(s - 1) < 1e-9;
        },
      ),
    );
  });
});
