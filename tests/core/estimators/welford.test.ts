import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { create, all } from 'mathjs';
import { Welford } from '../../../src/core/estimators/welford';
import { Rng } from '../../../src/core/random';

const M = create(all, { number: 'BigNumber', precision: 60 });

/** Mean and unbiased variance of xs in 60-digit BigNumber arithmetic. */
function bigStats(xs: number[]): { mean: number; variance: number } {
  const n = M.bignumber(xs.length);
  let s = M.bignumber(0);
  for (const x of xs) s = M.add(s, M.bignumber(x)) as never;
  const mean = M.divide(s, n) as never;
  let q = M.bignumber(0);
  for (const x of xs) {
    const d = M.subtract(M.bignumber(x), mean);
    q = M.add(q, M.multiply(d, d)) as never;
  }
  return { mean: M.number(mean), variance: M.number(M.divide(q, M.subtract(n, 1)) as never) };
}

describe('Welford', () => {
  it('matches a BigNumber mean and variance with a huge offset (no cancellation)', () => {
    const rng = new Rng(7);
    const xs = Array.from({ length: 2000 }, () => 1e9 + rng.nextFloat());
    const w = new Welford();
    for (const x of xs) w.add(x);
    const ref = bigStats(xs);
    expect(Math.abs(w.mean - ref.mean) / ref.mean).toBeLessThan(1e-15);
    // variance of U[0,1) is 1/12; naive Σx² − N x̄² would lose every digit at offset 1e9
    expect(Math.abs(w.variance() - ref.variance) / ref.variance).toBeLessThan(1e-6);
    expect(w.standardError()).toBeCloseTo(Math.sqrt(ref.variance / xs.length), 9);
  });

  it('addArray equals repeated add', () => {
    const xs = Float64Array.from({ length: 100 }, (_, i) => Math.sin(i) * 3 + i / 7);
    const a = new Welford();
    const b = new Welford();
    for (const x of xs) a.add(x);
    b.addArray(xs, 0, 50);
    b.addArray(xs, 50);
    expect(b.count).toBe(100);
    expect(b.mean).toBeCloseTo(a.mean, 13);
    expect(b.variance()).toBeCloseTo(a.variance(), 12);
  });

  it('merge of any split equals the whole (property)', () => {
    fc.assert(
      fc.property(
        fc.array(fc.double({ min: -1e6, max: 1e6, noNaN: true }), { minLength: 2, maxLength: 60 }),
        fc.nat(),
        (xs, k) => {
          const cut = k % (xs.length + 1);
          const whole = new Welford();
          whole.addArray(xs);
          const left = new Welford();
          const right = new Welford();
          left.addArray(xs, 0, cut);
          right.addArray(xs, cut);
          left.merge(right);
          expect(left.count).toBe(whole.count);
          const scale = Math.max(1, ...xs.map(Math.abs));
          expect(Math.abs(left.mean - whole.mean)).toBeLessThanOrEqual(1e-12 * scale);
          expect(Math.abs(left.variance() - whole.variance())).toBeLessThanOrEqual(1e-9 * scale * scale);
        },
      ),
    );
  });

  it('edge cases: empty, one value, merge into empty, snapshot', () => {
    const w = new Welford();
    expect(w.variance()).toBe(0);
    expect(Number.isNaN(w.standardError())).toBe(true);
    w.add(5);
    expect(w.mean).toBe(5);
    expect(w.variance()).toBe(0);
    const e = new Welford();
    e.merge(w);
    expect(e.mean).toBe(5);
    expect(e.count).toBe(1);
    e.add(7);
    expect(e.variance()).toBe(2); // values 5, 7: mean 6, s² = (1 + 1)/1
    expect(e.populationVariance()).toBe(1);
    expect(e.relativeVariance()).toBeCloseTo(2 / 36, 15);
    const c = Welford.from(e.toJSON());
    expect(c.variance()).toBe(2);
    c.reset();
    expect(c.count).toBe(0);
  });
});
