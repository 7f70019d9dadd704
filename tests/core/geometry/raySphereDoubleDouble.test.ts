// Double-double arithmetic and ulp stepping, checked against exact BigNumber arithmetic.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { create, all, type BigNumber } from 'mathjs';
import {
  twoSum,
  twoProduct,
  ddAdd,
  ddMul,
  ddDiv,
  ddSqrt,
  ddSub,
  ddSign,
  nextUp,
  nextDown,
  nextAfterN,
  ulp,
  ulpDistance,
  type DD,
} from '../../../src/core/geometry';

const M = create(all, { number: 'BigNumber', precision: 1200 });

/** The exact value of a double as a BigNumber (decimal expansion of m·2^e, no rounding at 1200 digits). */
function big(x: number): BigNumber {
  if (x === 0) return M.bignumber(0);
  const buf = new DataView(new ArrayBuffer(8));
  buf.setFloat64(0, x);
  const bits = buf.getBigUint64(0);
  const sign = bits >> 63n ? -1 : 1;
  const expBits = Number((bits >> 52n) & 0x7ffn);
  let mant = bits & 0xfffffffffffffn;
  let e: number;
  if (expBits === 0) e = -1074;
  else {
    mant |= 1n << 52n;
    e = expBits - 1075;
  }
  const v = M.bignumber(mant.toString()).times(M.bignumber(2).pow(e)) as BigNumber;
  return sign < 0 ? (v.neg() as BigNumber) : v;
}
const bigDD = (x: DD) => big(x[0]).plus(big(x[1])) as BigNumber;
const relErr = (x: BigNumber, ref: BigNumber) => Number(x.minus(ref).abs().div(ref.abs()));

const finite = fc.double({ min: -1e150, max: 1e150, noNaN: true, noDefaultInfinity: true });

describe('TwoSum and TwoProduct are error-free', () => {
  it('twoSum: s + e equals a + b exactly, and s is the rounded sum', () => {
    fc.assert(
      fc.property(finite, finite, (a, b) => {
        const [s, e] = twoSum(a, b);
        return (
          s === a + b &&
          big(s)
            .plus(big(e))
            .eq(big(a).plus(big(b)))
        );
      }),
      { seed: 7, numRuns: 300 },
    );
  });
  it('twoProduct: p + e equals a·b exactly (Veltkamp split)', () => {
    const g = fc
      .double({ min: -1e100, max: 1e100, noNaN: true, noDefaultInfinity: true })
      .filter((x) => x === 0 || Math.abs(x) > 1e-100);
    fc.assert(
      fc.property(g, g, (a, b) => {
        const [p, e] = twoProduct(a, b);
        return (
          p === a * b &&
          big(p)
            .plus(big(e))
            .eq(big(a).times(big(b)))
        );
      }),
      { seed: 8, numRuns: 300 },
    );
  });
  it('twoProduct is exact on the hard cases 1 ± ulp and 2^27 + 1', () => {
    for (const [a, b] of [
      [nextUp(1), nextDown(1)],
      [134217729, 134217729],
      [0.1, 0.7],
      [1e8, 1e8 + 1],
    ]) {
      const [p, e] = twoProduct(a, b);
      expect(
        big(p)
          .plus(big(e))
          .eq(big(a).times(big(b))),
      ).toBe(true);
    }
  });
});

describe('double-double operations carry ~106 bits', () => {
  const g = fc.double({ min: 1e-50, max: 1e50, noNaN: true });
  const pair = fc.tuple(g, fc.double({ min: -1, max: 1, noNaN: true })).map(([h, t]): DD => {
    const lo = h * t * 2 ** -54; // |lo| ≤ ½ ulp-ish
    return twoSum(h, lo);
  });
  it('add, sub, mul, div, sqrt are accurate to < 1e-30 relative', () => {
    fc.assert(
      fc.property(pair, pair, (x, y) => {
        const X = bigDD(x);
        const Y = bigDD(y);
        const sum = relErr(bigDD(ddAdd(x, y)), X.plus(Y) as BigNumber);
        const prod = relErr(bigDD(ddMul(x, y)), X.times(Y) as BigNumber);
        const quot = relErr(bigDD(ddDiv(x, y)), X.div(Y) as BigNumber);
        const root = relErr(bigDD(ddSqrt(x)), X.sqrt() as BigNumber);
        return sum < 1e-30 && prod < 1e-30 && quot < 1e-30 && root < 1e-30;
      }),
      { seed: 9, numRuns: 200 },
    );
  });
  it('recovers a cancellation a plain double loses: (1e16 + 1) − 1e16 = 1', () => {
    const x = ddAdd([1e16, 0], [1, 0]);
    expect(ddSub(x, [1e16, 0])).toEqual([1, 0]);
    expect(1e16 + 1 - 1e16).toBe(0); // what doubles do
  });
  it('ddSign reads the sign from lo when hi is 0', () => {
    expect(ddSign([0, -1e-300])).toBe(-1);
    expect(ddSign([0, 0])).toBe(0);
    expect(ddSign([1, -1e-20])).toBe(1);
  });
});

describe('ulp stepping', () => {
  it('nextUp / nextDown around 1, 0 and negatives', () => {
    expect(nextUp(1)).toBe(1 + 2 ** -52);
    expect(nextDown(1)).toBe(1 - 2 ** -53);
    expect(nextUp(0)).toBe(Number.MIN_VALUE);
    expect(nextDown(0)).toBe(-Number.MIN_VALUE);
    expect(nextUp(-1)).toBe(-1 + 2 ** -53);
    expect(nextUp(Number.MAX_VALUE)).toBe(Infinity);
    expect(nextAfterN(1, 3)).toBe(1 + 3 * 2 ** -52);
    expect(nextAfterN(1, -2)).toBe(1 - 2 * 2 ** -53);
    expect(ulp(1)).toBe(2 ** -52);
    expect(ulp(1e8)).toBe(2 ** -26); // 1e8 ∈ [2^26, 2^27): ulp = 2^(26−52)
  });
  it('ulpDistance counts doubles across zero and is symmetric', () => {
    expect(ulpDistance(1, nextUp(nextUp(1)))).toBe(2);
    expect(ulpDistance(-Number.MIN_VALUE, Number.MIN_VALUE)).toBe(2);
    expect(ulpDistance(0, -0)).toBe(0);
    fc.assert(
      fc.property(
        finite,
        fc.integer({ min: -5, max: 5 }),
        (x, n) => ulpDistance(x, nextAfterN(x, n)) === Math.abs(n) || x === 0,
      ),
      { seed: 10 },
    );
  });
});
