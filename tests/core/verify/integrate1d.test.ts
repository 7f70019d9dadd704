import { describe, expect, it } from 'vitest';
import { create, all } from 'mathjs';
import { INTEGRATION_METHOD, integrate1D } from '../../../src/core/verify/integrate1d';

const M = create(all, { number: 'BigNumber', precision: 50 });
const big = (expr: string) => M.number(M.evaluate(expr) as never) as number;

describe('integrate1D (adaptive Gauss–Kronrod)', () => {
  it('exam Q4(a): ∫₀² (x + 2)² dx = 56/3 to full precision', () => {
    const r = integrate1D((x) => (x + 2) * (x + 2), 0, 2);
    expect(r.converged).toBe(true);
    expect(Math.abs(r.value - 56 / 3)).toBeLessThanOrEqual(2 * Number.EPSILON * (56 / 3));
    expect(r.method).toBe(INTEGRATION_METHOD);
  });

  it('smooth non-polynomial integrands against 50-digit BigNumber closed forms', () => {
    const cases: [(x: number) => number, number, number, string][] = [
      [Math.exp, -1, 3, 'exp(3) - exp(-1)'],
      [Math.sin, 0, 10, '1 - cos(10)'],
      [(x) => 1 / (1 + x * x), -5, 5, '2 * atan(5)'],
      [(x) => Math.sqrt(x), 0, 1, '2/3'],
      [(x) => Math.exp(-x * x), -6, 6, 'sqrt(pi) * erf(6)'],
    ];
    for (const [f, a, b, ref] of cases) {
      // erf isn't in BigNumber mathjs: erf(6) = 1 − 2.15e-17, so √π is exact enough in doubles
      const exact = ref.includes('erf') ? Math.sqrt(Math.PI) * (1 - 2.1519736712498913e-17) : big(ref);
      const r = integrate1D(f, a, b);
      expect(Math.abs(r.value - exact)).toBeLessThan(1e-14 * Math.max(1, Math.abs(exact)));
    }
  });

  it('reversed limits give the negative; empty interval gives 0', () => {
    expect(integrate1D((x) => x, 2, 0).value).toBeCloseTo(-2, 14);
    expect(integrate1D((x) => x, 1, 1).value).toBe(0);
  });

  it('reports a non-finite integrand and a divergent integral instead of a number', () => {
    const r = integrate1D((x) => (x > 0.5 ? NaN : 1), 0, 1);
    expect(Number.isNaN(r.value)).toBe(true);
    expect(r.nonFiniteAt).toBeGreaterThan(0.5);
    const d = integrate1D((x) => 1 / x, 0, 1, { maxIntervals: 300 });
    expect(d.converged).toBe(false);
  });
});
