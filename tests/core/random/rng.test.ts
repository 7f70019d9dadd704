import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { Rng, mix32, toSeed, TWO_POW_M53 } from '../../../src/core/random';

describe('Rng (xoshiro128**)', () => {
  it('is reproducible for the same seed and stream, and differs across seeds and streams', () => {
    const a = new Rng(42);
    const b = new Rng(42);
    const c = new Rng(43);
    const d = new Rng(42, 1);
    const sa = Array.from({ length: 8 }, () => a.nextUint32());
    const sb = Array.from({ length: 8 }, () => b.nextUint32());
    const sc = Array.from({ length: 8 }, () => c.nextUint32());
    const sd = Array.from({ length: 8 }, () => d.nextUint32());
    expect(sa).toEqual(sb);
    expect(sa).not.toEqual(sc);
    expect(sa).not.toEqual(sd);
  });

  it('returns doubles in [0, 1) on multiples of 2^-53 for any seed', () => {
    fc.assert(
      fc.property(fc.integer({ min: 0, max: 0xffffffff }), (seed) => {
        const r = new Rng(seed);
        for (let i = 0; i < 64; i++) {
          const x = r.nextFloat();
          if (!(x >= 0 && x < 1)) return false;
          if (!Number.isInteger(x / TWO_POW_M53)) return false;
        }
        return true;
      }),
    );
  });

  it('has uniform mean, variance and low bits (moments over 2e5 draws)', () => {
    const r = new Rng(7);
    const n = 200000;
    let s = 0;
    let s2 = 0;
    let lowBitOnes = 0;
    for (let i = 0; i < n; i++) {
      const x = r.nextFloat();
      s += x;
      s2 += x * x;
      // the lowest mantissa bit must be random too (a 32-bit-only generator would leave it 0)
      if ((x / TWO_POW_M53) % 2 === 1) lowBitOnes++;
    }
    const mean = s / n;
    const variance = s2 / n - mean * mean;
    // standard error of the mean is sqrt(1/12/n) ≈ 6.5e-4; 5σ bands
    expect(Math.abs(mean - 0.5)).toBeLessThan(5 * Math.sqrt(1 / 12 / n));
    expect(Math.abs(variance - 1 / 12)).toBeLessThan(0.002);
    expect(Math.abs(lowBitOnes / n - 0.5)).toBeLessThan(5 * Math.sqrt(0.25 / n));
  });

  it('passes a chi-square test of 64 equal bins', () => {
    const r = new Rng(123456789);
    const bins = new Float64Array(64);
    const n = 64 * 2000;
    for (let i = 0; i < n; i++) bins[Math.floor(r.nextFloat() * 64)]++;
    let chi2 = 0;
    for (const o of bins) chi2 += (o - 2000) ** 2 / 2000;
    // 63 dof: the 0.999 quantile is ≈ 103.4
    expect(chi2).toBeLessThan(103.4);
  });

  it('has no serial correlation between consecutive draws', () => {
    const r = new Rng(99);
    const n = 100000;
    let prev = r.nextFloat();
    let sxy = 0;
    for (let i = 0; i < n; i++) {
      const x = r.nextFloat();
      sxy += (x - 0.5) * (prev - 0.5);
      prev = x;
    }
    // correlation estimate: sxy / n / (1/12); its sd ≈ 1/sqrt(n)
    expect(Math.abs(sxy / n / (1 / 12))).toBeLessThan(5 / Math.sqrt(n));
  });

  it('nextInt is unbiased on a non-power-of-two range and stays in range', () => {
    const r = new Rng(5);
    const counts = [0, 0, 0];
    for (let i = 0; i < 30000; i++) counts[r.nextInt(3)]++;
    for (const c of counts)
      expect(Math.abs(c - 10000)).toBeLessThan(5 * Math.sqrt(30000 * (1 / 3) * (2 / 3)));
    expect(r.nextInt(0)).toBe(0);
  });

  it('fill writes into the caller buffer without reallocating', () => {
    const buf = new Float64Array(16);
    const out = new Rng(1).fill(buf);
    expect(out).toBe(buf);
    const again = new Rng(1);
    for (let i = 0; i < 16; i++) expect(buf[i]).toBe(again.nextFloat());
  });

  it('fill gives exactly the nextFloat stream, in any ranges, and leaves the generator where nextFloat would', () => {
    for (const [seed, stream] of [
      [0, 0],
      [1, 7],
      [0xffffffff, 3],
      [123456789, 0x4d43],
    ] as const) {
      const want = new Rng(seed, stream);
      const got = new Rng(seed, stream);
      const buf = new Float64Array(3000).fill(-1);
      got.fill(buf, 0, 1000);
      got.fill(buf, 1000, 1001);
      got.fill(buf, 1001, 1001); // empty range: no draw
      got.fill(buf, 1001);
      for (let i = 0; i < buf.length; i++) expect(buf[i]).toBe(want.nextFloat());
      expect(got.nextUint32()).toBe(want.nextUint32());
      expect(got.nextFloat()).toBe(want.nextFloat());
    }
  });

  it('toSeed coerces garbage to a valid uint32 and mix32 avalanches', () => {
    expect(toSeed(NaN)).toBe(0);
    expect(toSeed(Infinity)).toBe(0);
    expect(toSeed(-1)).toBe(0xffffffff);
    expect(toSeed(2 ** 32 + 5)).toBe(5);
    expect(toSeed(3.9)).toBe(3);
    // flipping one input bit flips about half of the output bits
    let flips = 0;
    for (let i = 0; i < 256; i++) {
      const d = mix32(i) ^ mix32(i ^ 1);
      flips += popcount(d);
    }
    expect(flips / 256).toBeGreaterThan(12);
    expect(flips / 256).toBeLessThan(20);
  });
});

function popcount(x: number): number {
  let c = 0;
  for (let v = x >>> 0; v; v >>>= 1) c += v & 1;
  return c;
}
