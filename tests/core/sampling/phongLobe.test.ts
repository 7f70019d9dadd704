import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  invertPhongLobeSample,
  phongLobePdf,
  phongThetaCdf,
  phongThetaPdf,
  samplePhongLobe,
  samplePhongLobeBatch,
} from '../../../src/core/sampling/phongLobe';
import { Rng } from '../../../src/core/random';
import { STRESS_PAIRS, norm3, torusDist } from './stress';

const unit = fc.double({ min: 0, max: 1, maxExcluded: true, noNaN: true });
const EXPONENTS = [0, 1, 8, 100, 1e4];

function simpson(f: (x: number) => number, a: number, b: number, n = 4000): number {
  const h = (b - a) / n;
  let s = f(a) + f(b);
  for (let i = 1; i < n; i++) s += (i % 2 ? 4 : 2) * f(a + i * h);
  return (s * h) / 3;
}

describe('Phong lobe (n+1)/(2π) cosⁿθ', () => {
  it('normalized: ∫ p dω = 1 for several exponents', () => {
    for (const n of [0, 1, 8, 100]) {
      const v = 2 * Math.PI * simpson((t) => phongLobePdf(Math.cos(t), n) * Math.sin(t), 0, Math.PI / 2);
      expect(v).toBeCloseTo(1, 8);
      expect(simpson((t) => phongThetaPdf(t, n), 0, Math.PI / 2)).toBeCloseTo(1, 8);
      for (const t of [0.05, 0.3, 1.2]) expect(phongThetaCdf(t, n)).toBeCloseTo(simpson((s) => phongThetaPdf(s, n), 0, t), 8);
    }
  });

  it('n = 0 is uniform, n = 1 is the cosine lobe', () => {
    expect(phongLobePdf(0.3, 0)).toBeCloseTo(1 / (2 * Math.PI), 15);
    expect(phongLobePdf(0.3, 1)).toBeCloseTo(0.3 / Math.PI, 15);
  });

  it('stress inputs finite, unit length, z ≥ 0, for every exponent', () => {
    const out = new Float64Array(3);
    for (const n of EXPONENTS)
      for (const [a, b] of STRESS_PAIRS) {
        samplePhongLobe(a, b, n, out);
        expect(out.every(Number.isFinite)).toBe(true);
        expect(out[2]).toBeGreaterThanOrEqual(0);
        expect(Math.abs(norm3(out) - 1)).toBeLessThan(1e-15);
        expect(Number.isFinite(phongLobePdf(out[2], n))).toBe(true);
      }
  });

  it('round trip (property over u and exponent)', () => {
    const out = [0, 0, 0];
    fc.assert(
      fc.property(unit, unit, fc.constantFrom(...EXPONENTS), (a, b, n) => {
        samplePhongLobe(a, b, n, out);
        const [u1, u2] = invertPhongLobeSample(out[0], out[1], out[2], n);
        const sinT = Math.hypot(out[0], out[1]);
        return Math.abs(u1 - a) < 1e-9 && (sinT < 1e-6 || torusDist(u2, b) < 1e-9);
      }),
      { numRuns: 2000, seed: 8 },
    );
  });

  it('pdf 0 below the horizon and for NaN', () => {
    expect(phongLobePdf(-0.1, 8)).toBe(0);
    expect(phongLobePdf(Number.NaN, 8)).toBe(0);
    expect(phongThetaPdf(2, 8)).toBe(0);
  });

  it('batch equals scalar', () => {
    const n = 500;
    const u = new Rng(4).fill(new Float64Array(2 * n));
    const out = samplePhongLobeBatch(u, new Float64Array(3 * n), n, 8);
    const one = new Float64Array(3);
    for (let i = 0; i < n; i++) {
      samplePhongLobe(u[2 * i], u[2 * i + 1], 8, one);
      expect([out[3 * i], out[3 * i + 1], out[3 * i + 2]]).toEqual([one[0], one[1], one[2]]);
    }
  });

  it('E[cos θ] = (n+1)/(n+2) within 4σ (n = 8)', () => {
    const rng = new Rng(5);
    const out = [0, 0, 0];
    const N = 100000;
    let s = 0;
    let s2 = 0;
    for (let i = 0; i < N; i++) {
      samplePhongLobe(rng.nextFloat(), rng.nextFloat(), 8, out);
      s += out[2];
      s2 += out[2] ** 2;
    }
    const mean = s / N;
    expect(Math.abs(mean - 9 / 10)).toBeLessThan(4 * Math.sqrt((s2 / N - mean * mean) / N));
  });
});
