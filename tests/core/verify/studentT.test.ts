import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { lnGamma, regularizedBeta, studentTCdf, studentTTwoSided } from '../../../src/core/verify/studentT';

describe('lnGamma', () => {
  it('matches ln((n − 1)!) and Γ(1/2) = √π', () => {
    let fact = 1;
    for (let n = 1; n <= 20; n++) {
      expect(lnGamma(n)).toBeCloseTo(Math.log(fact), 12);
      fact *= n;
    }
    expect(lnGamma(0.5)).toBeCloseTo(0.5 * Math.log(Math.PI), 13);
    expect(lnGamma(0.25)).toBeCloseTo(Math.log(3.625609908221908), 12);
    expect(lnGamma(0)).toBeNaN();
  });
});

describe('regularizedBeta', () => {
  it('matches the closed forms I_x(1, b) = 1 − (1 − x)^b, I_x(a, 1) = x^a, I_x(2, 2) = 3x² − 2x³', () => {
    for (const x of [1e-6, 0.01, 0.3, 0.5, 0.77, 0.999]) {
      for (const b of [0.5, 1, 2.5, 7]) expect(regularizedBeta(x, 1, b)).toBeCloseTo(1 - (1 - x) ** b, 13);
      for (const a of [0.5, 3, 11]) expect(regularizedBeta(x, a, 1)).toBeCloseTo(x ** a, 13);
      expect(regularizedBeta(x, 2, 2)).toBeCloseTo(3 * x * x - 2 * x ** 3, 13);
    }
  });
  it('is symmetric: I_x(a, b) + I_{1−x}(b, a) = 1, and increasing in x', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0.01, max: 0.99, noNaN: true }),
        fc.double({ min: 0.1, max: 50, noNaN: true }),
        fc.double({ min: 0.1, max: 50, noNaN: true }),
        (x, a, b) => {
          expect(regularizedBeta(x, a, b) + regularizedBeta(1 - x, b, a)).toBeCloseTo(1, 11);
          expect(regularizedBeta(Math.min(1, x + 0.01), a, b)).toBeGreaterThanOrEqual(
            regularizedBeta(x, a, b),
          );
        },
      ),
      { seed: 7, numRuns: 200 },
    );
  });
  it('refuses what is outside its domain', () => {
    expect(regularizedBeta(-0.1, 1, 1)).toBeNaN();
    expect(regularizedBeta(0.5, 0, 1)).toBeNaN();
    expect(regularizedBeta(0, 2, 3)).toBe(0);
    expect(regularizedBeta(1, 2, 3)).toBe(1);
  });
});

describe('Student t tail', () => {
  it('matches the closed forms for ν = 1 (Cauchy), 2 and 3', () => {
    for (const t of [0.001, 0.2, 1, 1.7, 4, 30, 1e4]) {
      expect(studentTTwoSided(t, 1)).toBeCloseTo(1 - (2 / Math.PI) * Math.atan(t), 13);
      expect(studentTTwoSided(-t, 2)).toBeCloseTo(1 - t / Math.sqrt(2 + t * t), 13);
      const u = t / Math.sqrt(3);
      expect(studentTTwoSided(t, 3)).toBeCloseTo(1 - (2 / Math.PI) * (u / (1 + u * u) + Math.atan(u)), 13);
    }
  });
  it('keeps its relative accuracy far in the tail (ν = 1: p ≈ 2/(πt))', () => {
    const t = 1e8;
    // 1 − (2/π) atan t = (2/π) atan(1/t) for t > 0, without cancellation
    const exact = (2 / Math.PI) * Math.atan(1 / t);
    expect(Math.abs(studentTTwoSided(t, 1) / exact - 1)).toBeLessThan(1e-12);
  });
  it('gives α at the t-table quantiles t_{1−α/2, ν} (six-digit table values)', () => {
    const table: [number, number, number][] = [
      // [t, ν, two-sided α]
      [12.706205, 1, 0.05],
      [9.924843, 2, 0.01],
      [2.570582, 5, 0.05],
      [2.228139, 10, 0.05],
      [1.724718, 20, 0.1],
      [2.749996, 30, 0.01],
      [1.959966, 1e6, 0.05],
    ];
    for (const [t, dof, alpha] of table)
      expect(Math.abs(studentTTwoSided(t, dof) - alpha)).toBeLessThan(2e-6);
  });
  it('has the edge values and the CDF is its one-sided half', () => {
    expect(studentTTwoSided(0, 4)).toBe(1);
    expect(studentTTwoSided(Infinity, 4)).toBe(0);
    expect(studentTTwoSided(NaN, 4)).toBeNaN();
    expect(studentTTwoSided(1, 0)).toBeNaN();
    expect(studentTCdf(2.228139, 10)).toBeCloseTo(0.975, 6);
    expect(studentTCdf(-2.228139, 10)).toBeCloseTo(0.025, 6);
  });
});
