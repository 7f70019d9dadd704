import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { create, all, type BigNumber } from 'mathjs';
import { chi2Test, chi2UpperTail, sidakAlpha } from '../../../src/core/verify';

const M = create(all, { number: 'BigNumber', precision: 80 });
const big = (x: number | string): BigNumber => M.bignumber(x);

/**
 * Reference Q(a, y) = 1 − P(a, y) in 80-digit BigNumber arithmetic, with the power series
 * P(a, y) = y^a e^{-y} Σ_k y^k / Γ(a + k + 1) (Abramowitz & Stegun 6.5.29). Accurate for the
 * moderate y used here (Q ≥ 1e-60, series converges once k > y).
 */
function refQ(a: number, y: number): number {
  const A = big(a);
  const Y = big(y);
  // Γ(a + 1) for a = m/2: Γ(1/2) = √π, Γ(1) = 1, Γ(z + 1) = z Γ(z)
  let gamma = Number.isInteger(a) ? big(1) : (M.sqrt(M.pi as unknown as BigNumber) as BigNumber);
  let z = Number.isInteger(a) ? big(1) : big(0.5);
  while (M.smaller(z, M.add(A, 1))) {
    gamma = M.multiply(gamma, z) as BigNumber;
    z = M.add(z, 1) as BigNumber;
  }
  let term = M.divide(1, gamma) as BigNumber; // y^0 / Γ(a + 1)
  let sum = term;
  for (let k = 1; k < 4000; k++) {
    term = M.divide(M.multiply(term, Y), M.add(A, k)) as BigNumber;
    sum = M.add(sum, term) as BigNumber;
    if (M.smaller(term, M.multiply(sum, big('1e-70')))) break;
  }
  const p = M.multiply(M.multiply(M.pow(Y, A), M.exp(M.unaryMinus(Y))), sum) as BigNumber;
  return M.number(M.subtract(1, p) as BigNumber) as number;
}

describe('chi2UpperTail', () => {
  it('equals exp(−x/2) exactly for dof = 2, far into the tail', () => {
    for (const x of [1e-8, 0.5, 1, 10, 100, 700, 1000, 1400]) {
      const q = chi2UpperTail(x, 2);
      const ref = Math.exp(-x / 2);
      expect(Math.abs(q - ref)).toBeLessThanOrEqual(1e-12 * ref);
    }
  });

  it('matches the closed form e^{-y} Σ_{k<m} y^k/k! (BigNumber) for even dof at x = 1000', () => {
    for (const dof of [4, 10, 30]) {
      const m = dof / 2;
      const y = big(500);
      let s = big(0);
      let t = big(1);
      for (let k = 0; k < m; k++) {
        s = M.add(s, t) as BigNumber;
        t = M.divide(M.multiply(t, y), k + 1) as BigNumber;
      }
      const ref = M.number(M.multiply(M.exp(M.unaryMinus(y)), s) as BigNumber) as number;
      const q = chi2UpperTail(1000, dof);
      expect(ref).toBeGreaterThan(0);
      expect(Math.abs(q - ref) / ref).toBeLessThan(1e-12);
    }
  });

  it('matches an 80-digit series reference for odd and even dof', () => {
    for (const dof of [1, 3, 7, 19, 20, 99]) {
      for (const x of [0.01, 1, dof, 3 * dof + 10, 60]) {
        const ref = refQ(dof / 2, x / 2);
        const q = chi2UpperTail(x, dof);
        expect(Math.abs(q - ref) / ref, `dof=${dof} x=${x}`).toBeLessThan(1e-12);
      }
    }
  });

  it('keeps 1e-12 relative accuracy far in the tail for odd dof (erfc continued fraction, BigNumber)', () => {
    // Q(1/2, y) = erfc(√y), erfc z = e^{-z²}/√π · 1/(z + (1/2)/(z + 1/(z + (3/2)/(z + …)))) (A&S 7.1.14),
    // evaluated backwards in 80 digits; then Q(a + 1, y) = Q(a, y) + y^a e^{-y} / Γ(a + 1) (A&S 6.5.21).
    for (const x of [200, 600, 1000, 1400]) {
      const y = big(x / 2);
      const z = M.sqrt(y) as BigNumber;
      let t = z;
      for (let k = 600; k >= 1; k--) t = M.add(z, M.divide(big(k / 2), t)) as BigNumber;
      const pi = M.pi as unknown as BigNumber;
      let q = M.divide(M.exp(M.unaryMinus(y)), M.multiply(M.sqrt(pi), t)) as BigNumber; // Q(1/2, y)
      let a = big(0.5);
      let gamma = M.sqrt(pi) as BigNumber; // Γ(1/2)
      for (const dof of [1, 3, 5, 7]) {
        const ref = M.number(q) as number;
        const got = chi2UpperTail(x, dof);
        expect(ref).toBeGreaterThan(0);
        expect(Math.abs(got - ref) / ref, `dof=${dof} x=${x}`).toBeLessThan(1e-12);
        // step a → a + 1
        gamma = M.multiply(gamma, a) as BigNumber; // Γ(a + 1) = a Γ(a)
        q = M.add(
          q,
          M.divide(M.multiply(M.pow(y, a) as BigNumber, M.exp(M.unaryMinus(y))), gamma),
        ) as BigNumber;
        a = M.add(a, 1) as BigNumber;
      }
    }
  });

  it('reproduces textbook critical values', () => {
    // qchisq(0.95, 1) = 3.841458820694124, qchisq(0.99, 1) = 6.634896601021214 (R)
    expect(chi2UpperTail(3.841458820694124, 1)).toBeCloseTo(0.05, 12);
    expect(chi2UpperTail(6.634896601021214, 1)).toBeCloseTo(0.01, 12);
  });

  it('handles the domain edges', () => {
    expect(chi2UpperTail(0, 3)).toBe(1);
    expect(chi2UpperTail(-5, 3)).toBe(1);
    expect(chi2UpperTail(Infinity, 3)).toBe(0);
    expect(chi2UpperTail(NaN, 3)).toBeNaN();
    expect(chi2UpperTail(1, 0)).toBeNaN();
  });

  it('is a decreasing function of x with values in [0, 1] (property)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 2000, noNaN: true }),
        fc.double({ min: 0, max: 2000, noNaN: true }),
        fc.integer({ min: 1, max: 500 }),
        (a, b, dof) => {
          const lo = Math.min(a, b);
          const hi = Math.max(a, b);
          const qlo = chi2UpperTail(lo, dof);
          const qhi = chi2UpperTail(hi, dof);
          return qlo >= 0 && qlo <= 1 && qhi >= 0 && qhi <= qlo + 1e-15;
        },
      ),
    );
  });
});

describe('sidakAlpha', () => {
  it('is alpha for one test and matches BigNumber for many tests with tiny alpha', () => {
    expect(sidakAlpha(0.01, 1)).toBeCloseTo(0.01, 15);
    for (const [a, m] of [
      [1e-10, 1000],
      [0.01, 7],
      [0.05, 1e6],
    ] as const) {
      const ref = M.number(
        M.subtract(
          1,
          M.pow(M.subtract(1, big(a)) as BigNumber, M.divide(1, big(m)) as BigNumber) as BigNumber,
        ) as BigNumber,
      ) as number;
      expect(Math.abs(sidakAlpha(a, m) - ref) / ref).toBeLessThan(1e-13);
    }
  });
  it('is below alpha/m·(1 + alpha) and at least alpha/m (property)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 1e-12, max: 0.5, noNaN: true }),
        fc.integer({ min: 1, max: 1e6 }),
        (a, m) => {
          const s = sidakAlpha(a, m);
          return s >= (a / m) * (1 - 1e-12) && s <= a;
        },
      ),
    );
  });
});

describe('chi2Test', () => {
  it('accepts a perfect fit with statistic 0 and p = 1', () => {
    const e = [10, 20, 30, 40];
    const r = chi2Test(e, e);
    expect(r.statistic).toBe(0);
    expect(r.dof).toBe(3);
    expect(r.pValue).toBe(1);
    expect(r.pass).toBe(true);
  });

  it('computes Pearson’s statistic by hand', () => {
    const r = chi2Test([12, 18, 30, 40], [10, 20, 30, 40]);
    expect(r.statistic).toBeCloseTo(0.4 + 0.2, 14);
    expect(r.dof).toBe(3);
    expect(r.pValue).toBeCloseTo(chi2UpperTail(0.6, 3), 15);
  });

  it('pools bins with expected < minExpected into one bin', () => {
    // bins with E = 1, 2, 1 are pooled (E = 4 < 5, so the next-smallest (E = 10) joins too)
    const r = chi2Test([1, 2, 1, 10, 50, 36], [1, 2, 1, 10, 50, 36]);
    expect(r.pooledBins).toBe(4);
    expect(r.dof).toBe(2); // pooled + 50 + 36 = 3 bins → dof 2
    expect(r.pass).toBe(true);
  });

  it('fails when a sample lands in a bin of zero expectation', () => {
    const r = chi2Test([1, 50, 50], [0, 50.5, 50.5]);
    expect(r.pass).toBe(false);
    expect(r.pValue).toBe(0);
    expect(r.note).toMatch(/predicts none/);
  });

  it('rejects a gross misfit and reports bad input clearly', () => {
    expect(chi2Test([100, 0, 0], [33, 33, 34]).pass).toBe(false);
    expect(chi2Test([1, 2], [1]).note).toMatch(/bins/);
    expect(chi2Test([1, 2], [1, NaN]).note).toMatch(/not finite/);
    const few = chi2Test([10], [10]);
    expect(few.note).toMatch(/too few bins/);
    expect(few.pValue).toBeNaN(); // not applicable, not a rejection
    expect(few.pass).toBe(false);
  });

  it('uses the Šidák-corrected level', () => {
    const r = chi2Test([12, 18, 30, 40], [10, 20, 30, 40], { alpha: 0.01, tests: 10 });
    expect(r.sidakAlpha).toBeCloseTo(sidakAlpha(0.01, 10), 15);
    expect(r.sidakAlpha).toBeLessThan(0.01);
  });
});
