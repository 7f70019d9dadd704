// The exam's inversion formulas in float32 against float64: where each form fails, where the
// stable twins hold, and the GPU pass's hash.
import { describe, expect, it } from 'vitest';
import {
  EXAM_C_F32,
  gpuXi,
  pcgHash,
  phiLnF32,
  phiLog1pF32,
  phiRef64,
  thetaAcosF32,
  thetaAsinF32,
  thetaRef64,
  warpF32Table,
} from '../../../src/core/sampling';
import { ulpF32 } from '../../../src/core/geometry';
import { examLobePdf, uniformHemispherePdf } from '../../../src/core/sampling';
import { hemisphereChi2 } from '../../../src/core/verify';

const ulps = (x: number, ref: number) => Math.abs(x - ref) / ulpF32(ref);

describe('θ in float32', () => {
  it('½ arccos(1 − 2ξ) returns 0 once ξ < 2⁻²⁵ (1 − 2ξ rounds to 1); arcsin √ξ keeps it', () => {
    for (const xi of [2 ** -26, 2 ** -30, 1e-9]) {
      expect(thetaAcosF32(xi)).toBe(0);
      expect(ulps(thetaAsinF32(xi), thetaRef64(Math.fround(xi)))).toBeLessThanOrEqual(1);
    }
    // just above the threshold the arccos form keeps only a few bits (ξ not a power of two)
    let worst = 0;
    for (let j = 0; j < 20; j++) {
      const x = Math.fround(1e-7 * (1 + j / 7));
      worst = Math.max(worst, Math.abs(thetaAcosF32(x) - thetaRef64(x)) / thetaRef64(x));
      expect(ulps(thetaAsinF32(x), thetaRef64(x))).toBeLessThanOrEqual(1);
    }
    expect(worst).toBeGreaterThan(1e-2);
  });

  it('near ξ → 1 arcsin √ξ magnifies the rounding of √ξ; ½ arccos(1 − 2ξ) is fine', () => {
    let worstAsin = 0;
    let worstAcos = 0;
    for (let k = 1; k <= 50; k++) {
      const xi = 1 - k * 2 ** -24; // float32 values just below 1
      worstAsin = Math.max(worstAsin, ulps(thetaAsinF32(xi), thetaRef64(xi)));
      worstAcos = Math.max(worstAcos, ulps(thetaAcosF32(xi), thetaRef64(xi)));
    }
    expect(worstAsin).toBeGreaterThan(100);
    expect(worstAcos).toBeLessThanOrEqual(2);
  });

  it('in the middle both forms are within 2 float32 ulps', () => {
    for (const xi of [0.1, 0.3, 0.5, 0.7]) {
      const x = Math.fround(xi);
      expect(ulps(thetaAcosF32(x), thetaRef64(x))).toBeLessThanOrEqual(2);
      expect(ulps(thetaAsinF32(x), thetaRef64(x))).toBeLessThanOrEqual(2);
    }
  });
});

describe('φ in float32', () => {
  it('ln(c ξ + 1) loses the relative precision of small ξ; log1p keeps it', () => {
    const xi = Math.fround(1e-9); // c ξ ≈ 5·10⁻⁷: c ξ + 1 keeps only ~4 of its bits
    expect(Math.abs(phiLnF32(xi) - phiRef64(xi)) / phiRef64(xi)).toBeGreaterThan(1e-3);
    expect(ulps(phiLog1pF32(xi), phiRef64(xi))).toBeLessThanOrEqual(2);
    const tiny = 2 ** -40;
    expect(phiLnF32(tiny)).toBe(0);
    expect(phiLog1pF32(tiny)).toBeGreaterThan(0);
  });

  it('near ξ → 1 both are within a couple of ulps of 2π', () => {
    const xi = Math.fround(1 - 2 ** -24);
    expect(ulps(phiLnF32(xi), phiRef64(xi))).toBeLessThanOrEqual(2);
    expect(ulps(phiLog1pF32(xi), phiRef64(xi))).toBeLessThanOrEqual(2);
    expect(EXAM_C_F32).toBeCloseTo(534.49, 2);
  });

  it('the table lists every form at every ξ', () => {
    const t = warpF32Table();
    expect(t.length).toBeGreaterThan(6);
    for (const row of t)
      expect(row.forms.map((f) => f.id)).toEqual(['theta-acos', 'theta-asin', 'phi-ln', 'phi-log1p']);
    const first = t[0].forms.find((f) => f.id === 'theta-acos')!;
    expect(first.relError).toBe(1); // θ = 0 for a sample whose θ is √ξ
  });
});

describe('the GPU pass’s hash', () => {
  it('matches PCG-RXS-M-XS on known values and gives 24-bit ξ', () => {
    // reference values computed by hand from the definition for v = 0 and v = 1
    const ref = (v: number) => {
      const s = (BigInt(v) * 747796405n + 2891336453n) & 0xffffffffn;
      const w = (((s >> ((s >> 28n) + 4n)) ^ s) * 277803737n) & 0xffffffffn;
      return Number(((w >> 22n) ^ w) & 0xffffffffn);
    };
    for (const v of [0, 1, 12345, 0xffffffff]) expect(pcgHash(v)).toBe(ref(v));
    for (let i = 0; i < 1000; i++) {
      const [a, b] = gpuXi(i, 7);
      expect(a).toBeGreaterThanOrEqual(0);
      expect(a).toBeLessThan(1);
      expect(Math.fround(a)).toBe(a);
      expect(Math.fround(b)).toBe(b);
    }
    // roughly uniform: the mean of 10⁴ ξ₁ within 0.01 of ½
    let s = 0;
    for (let i = 0; i < 10000; i++) s += gpuXi(i, 1)[0];
    expect(Math.abs(s / 10000 - 0.5)).toBeLessThan(0.01);
  });
});

describe('the GPU pass’s samples, emulated in float32', () => {
  /** Directions of samples 0 … n−1 from the hash and the stable float32 forms. */
  function sample(n: number, seed: number): Float64Array {
    const fr = Math.fround;
    const out = new Float64Array(3 * n);
    for (let i = 0; i < n; i++) {
      const [x1, x2] = gpuXi(i, seed);
      const s = fr(Math.sqrt(x1));
      const phi = Math.min(phiLog1pF32(x2), fr(6.283185));
      out[3 * i] = fr(s * fr(Math.cos(phi)));
      out[3 * i + 1] = fr(s * fr(Math.sin(phi)));
      out[3 * i + 2] = fr(Math.sqrt(fr(1 - x1)));
    }
    return out;
  }
  it('pass the χ² test against the exam pdf, and fail it against the uniform one', () => {
    const n = 200_000;
    const d = sample(n, 7);
    expect(hemisphereChi2(d, n, examLobePdf, { tests: 2 }).pass).toBe(true);
    expect(hemisphereChi2(d, n, uniformHemispherePdf, { tests: 2 }).pass).toBe(false);
  });
});
