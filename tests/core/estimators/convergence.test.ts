import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { ConvergenceSeries, logSpacedCounts } from '../../../src/core/estimators/convergence';
import { RmseAccumulator, quantile, rmse } from '../../../src/core/estimators/rmse';
import { fitLogLogSlope } from '../../../src/core/estimators/slope';
import { Welford } from '../../../src/core/estimators/welford';
import { Rng } from '../../../src/core/random';

describe('logSpacedCounts', () => {
  it('is strictly increasing, starts at nMin and ends at nMax (property)', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 1e7 }),
        fc.integer({ min: 1, max: 20 }),
        fc.integer({ min: 1, max: 100 }),
        (nMax, per, nMin) => {
          const c = logSpacedCounts(nMax, per, nMin);
          expect(c[0]).toBe(Math.min(nMin, nMax));
          expect(c[c.length - 1]).toBe(nMax);
          for (let i = 1; i < c.length; i++) expect(c[i]).toBeGreaterThan(c[i - 1]);
          for (const v of c) expect(Number.isInteger(v)).toBe(true);
          expect(c.length).toBeLessThanOrEqual(Math.ceil(Math.log10(nMax) * per) + 2);
        },
      ),
    );
  });
});

describe('ConvergenceSeries', () => {
  it('records the prefix means and standard errors at each checkpoint, in any batching', () => {
    const rng = new Rng(3);
    const terms = Float64Array.from({ length: 1000 }, () => rng.nextFloat() * 10);
    const cps = logSpacedCounts(1000, 5);
    const s = new ConvergenceSeries(cps, 5);
    // odd batch sizes across checkpoint boundaries
    for (let i = 0; i < terms.length; i += 37) s.push(terms, i, Math.min(terms.length, i + 37));
    expect(s.recorded).toBe(cps.length);
    for (let k = 0; k < cps.length; k++) {
      const n = cps[k];
      const w = new Welford();
      w.addArray(terms, 0, n);
      expect(s.estimate[k]).toBeCloseTo(w.mean, 12);
      expect(s.absError[k]).toBeCloseTo(Math.abs(w.mean - 5), 12);
      if (n > 1) expect(s.stderr[k]).toBeCloseTo(w.standardError(), 12);
      else expect(Number.isNaN(s.stderr[k])).toBe(true);
    }
  });

  it('skips non-finite terms without advancing N', () => {
    const s = new ConvergenceSeries([2], 0);
    s.push([1, NaN, 3]);
    expect(s.invalid).toBe(1);
    expect(s.estimate[0]).toBe(2);
  });
});

describe('RMSE and slopes', () => {
  it('rmse and quantile match closed forms', () => {
    expect(rmse([1, 3], 2)).toBe(1);
    expect(rmse([2, 2, 5], 2)).toBeCloseTo(Math.sqrt(3), 15);
    expect(quantile([4, 1, 3, 2], 0.5)).toBe(2.5);
    expect(quantile([4, 1, 3, 2], 0)).toBe(1);
    expect(quantile([4, 1, 3, 2], 1)).toBe(4);
    expect(Number.isNaN(quantile([], 0.5))).toBe(true);
  });

  it('fits an exact power law and ignores zero errors', () => {
    const x = [10, 100, 1000, 10000, 5];
    const y = x.map((n) => 3 * n ** -0.5);
    y[4] = 0;
    const fit = fitLogLogSlope(x, y);
    expect(fit.slope).toBeCloseTo(-0.5, 12);
    expect(fit.intercept).toBeCloseTo(Math.log10(3), 12);
    expect(fit.points).toBe(4);
    expect(fit.r2).toBeCloseTo(1, 12);
    expect(Number.isNaN(fitLogLogSlope([1], [1]).slope)).toBe(true);
  });

  it('RMSE over independent uniform-MC runs falls like N^-1/2 and matches σ/√N', () => {
    const f = (x: number) => (x + 2) * (x + 2);
    const I = 56 / 3;
    const sigma = Math.sqrt(2 * ((4 ** 5 - 2 ** 5) / 5) - I * I); // per-term σ of 2 f(U)
    const cps = logSpacedCounts(4096, 3, 16);
    const R = 400;
    const acc = new RmseAccumulator(cps, I, R);
    const buf = new Float64Array(4096);
    for (let r = 0; r < R; r++) {
      const rng = new Rng(99, r);
      for (let i = 0; i < buf.length; i++) buf[i] = 2 * f(2 * rng.nextFloat());
      const s = new ConvergenceSeries(cps, I);
      s.push(buf);
      acc.addRun(s);
    }
    const sum = acc.summary();
    for (let k = 0; k < cps.length; k++) {
      const expected = sigma / Math.sqrt(cps[k]);
      // RMSE over 400 runs has relative sd ≈ 1/√(2·400) ≈ 3.5 %: allow 15 %
      expect(Math.abs(sum.rmse[k] - expected) / expected).toBeLessThan(0.15);
      expect(sum.lo[k]).toBeLessThan(sum.hi[k]);
      expect(Math.abs(sum.mean[k] - I)).toBeLessThan((4 * expected) / Math.sqrt(R));
    }
    const fit = fitLogLogSlope(sum.n, sum.rmse);
    expect(Math.abs(fit.slope + 0.5)).toBeLessThan(0.05);
  });
});
