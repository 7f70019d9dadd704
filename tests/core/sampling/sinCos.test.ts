/**
 * writeScaledCosSin against 50-digit mathjs BigNumber references: absolute error within 2⁻⁵³ on
 * [0, 2π] (the azimuth range of every warp), good relative accuracy at the zeros of sin and cos
 * (quadrant boundaries, where a careless reduction loses everything), and the Math fallback.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { create, all, type BigNumber } from 'mathjs';
import { writeScaledCosSin } from '../../../src/core/sampling/sinCos';
import { Rng } from '../../../src/core/random';

const M = create(all, { number: 'BigNumber', precision: 50 });
/** The double's exact value m·2^e as a BigNumber (its shortest decimal is not exact, and near
 * kπ/2 the difference is the whole answer). */
function big(x: number): BigNumber {
  if (x === 0) return M.bignumber(0);
  const bits = new BigUint64Array(new Float64Array([Math.abs(x)]).buffer)[0];
  const e = Number((bits >> 52n) & 0x7ffn);
  const frac = bits & ((1n << 52n) - 1n);
  const mant = e === 0 ? frac : frac | (1n << 52n);
  const exp = (e === 0 ? 1 : e) - 1075;
  const v = M.multiply(
    M.bignumber(mant.toString()),
    M.pow(M.bignumber(2), M.bignumber(exp)),
  ) as unknown as BigNumber;
  return x < 0 ? (M.unaryMinus(v) as BigNumber) : v;
}
function ref(phi: number): [number, number] {
  const b = big(phi);
  return [Number(M.cos(b).toString()), Number(M.sin(b).toString())];
}

const ULP1 = 2 ** -52; // spacing of doubles in [1, 2)
const out = new Float64Array(2);

function check(phi: number) {
  writeScaledCosSin(phi, 1, out, 0);
  const [c, s] = ref(phi);
  expect(Math.abs(out[0] - c), `cos ${phi}`).toBeLessThanOrEqual(ULP1 / 2);
  expect(Math.abs(out[1] - s), `sin ${phi}`).toBeLessThanOrEqual(ULP1 / 2);
  // where a value is small (near a quadrant boundary) it must still be right relative to itself
  for (const [got, want] of [
    [out[0], c],
    [out[1], s],
  ] as const) {
    if (Math.abs(want) < 1e-3 && want !== 0)
      expect(Math.abs(got - want) / Math.abs(want), `rel ${phi}`).toBeLessThan(4 * 2 ** -53);
  }
}

describe('writeScaledCosSin', () => {
  it('matches BigNumber cos/sin within 2⁻⁵³ on a grid over [0, 2π] and at random angles', () => {
    for (let i = 0; i <= 400; i++) check((i / 400) * 2 * Math.PI);
    const rng = new Rng(31);
    for (let i = 0; i < 400; i++) check(rng.nextFloat() * 2 * Math.PI);
  });

  it('is accurate at and around every quadrant boundary kπ/2 (the zeros of sin and cos)', () => {
    for (let k = 0; k <= 4; k++) {
      const b = (k * Math.PI) / 2;
      for (const d of [0, 1e-300, 2 ** -60, 2 ** -52, 1e-12, 1e-8, 1e-4, -1e-4, -1e-8, -(2 ** -52)])
        check(b + d);
      // the neighbouring doubles of the boundary
      const f = new Float64Array([b]);
      const u = new BigUint64Array(f.buffer);
      if (b > 0) {
        u[0] -= 1n;
        check(f[0]);
        u[0] += 2n;
        check(f[0]);
      }
    }
    check(6.283185307179585); // the largest φ the warps produce (just below 2π)
  });

  it('scales by s and handles negative angles (property)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -50, max: 50, noNaN: true }),
        fc.double({ min: -4, max: 4, noNaN: true }),
        (phi, s) => {
          writeScaledCosSin(phi, s, out, 0);
          return (
            Math.abs(out[0] - s * Math.cos(phi)) <= 4 * ULP1 * Math.max(1, Math.abs(s)) &&
            Math.abs(out[1] - s * Math.sin(phi)) <= 4 * ULP1 * Math.max(1, Math.abs(s))
          );
        },
      ),
      { numRuns: 2000, seed: 5 },
    );
  });

  it('defers to Math.cos/Math.sin outside the reduction’s domain and for non-finite input', () => {
    for (const phi of [1e6, -3e9, 1e300, NaN, Infinity]) {
      writeScaledCosSin(phi, 2, out, 0);
      expect(out[0]).toBe(2 * Math.cos(phi));
      expect(out[1]).toBe(2 * Math.sin(phi));
    }
  });

  it('writes at the given offset into plain arrays too', () => {
    const arr = [9, 9, 9, 9];
    writeScaledCosSin(Math.PI / 3, 2, arr, 2);
    expect(arr[0]).toBe(9);
    expect(arr[2]).toBeCloseTo(1, 15);
    expect(arr[3]).toBeCloseTo(Math.sqrt(3), 15);
  });
});
