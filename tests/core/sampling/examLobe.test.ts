import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { all, create } from 'mathjs';
import {
  EXAM_E2PI_M1,
  examLobeK,
  examLobePdf,
  examLobeThetaPhiPdf,
  examPhiCdf,
  examPhiPdf,
  examThetaCdf,
  examThetaPdf,
  invertedJacobianDensity,
  invertedJacobianPartialIntegral,
  sampleExamLobe,
} from '../../../src/core/sampling/examLobe';
import { exactDecimal } from '../../../src/core/sampling/stability';
import { Rng } from '../../../src/core/random';
import { STRESS_U } from './stress';

// mathjs' typings do not follow BigNumber through generic calls; the instance is used untyped here.
const m: any = create(all, { number: 'BigNumber', precision: 60 });
type BN = ReturnType<typeof m.bignumber>;
const big = (x: number) => m.bignumber(exactDecimal(x));
const num = (b: unknown) => Number((b as BN).toString());
const twoPiB = m.multiply(m.bignumber(2), m.pi) as BN;
const cB = m.subtract(m.exp(twoPiB), 1) as BN; // e^{2π} − 1
const relErr = (a: number, b: number) => Math.abs(a - b) / Math.abs(b);
/** ln(1 + y) at 60 digits, by series for tiny y (1 + y would round). */
const log1pB = (y: BN): BN =>
  (m.smaller(y, m.bignumber('1e-12'))
    ? m.add(m.subtract(y, m.divide(m.pow(y, 2), 2)), m.divide(m.pow(y, 3), 3))
    : m.log(m.add(y, 1))) as BN;

/** Simpson's rule on [a, b] with n (even) panels. */
function simpson(f: (x: number) => number, a: number, b: number, n = 2000): number {
  const h = (b - a) / n;
  let s = f(a) + f(b);
  for (let i = 1; i < n; i++) s += (i % 2 ? 4 : 2) * f(a + i * h);
  return (s * h) / 3;
}

describe('exam lobe p(ω) = k cos θ e^φ', () => {
  it('k = 2/(e^{2π} − 1) to within 1 ulp of the 60-digit value', () => {
    const ref = num(m.divide(m.bignumber(2), cB));
    // two roundings (expm1, division): within 2 ulps
    expect(Math.abs(examLobeK() - ref)).toBeLessThanOrEqual(2 * 2 ** -61); // ulp(k) = 2^-61 (k ≈ 3.7e-3)
    expect(Math.abs(EXAM_E2PI_M1 - num(cB))).toBeLessThanOrEqual(2 ** -43); // one ulp of ≈ 534.5
  });

  it('normalizes: ∫∫ k cos θ sin θ e^φ dθ dφ = 1 (Simpson, separable)', () => {
    const th = simpson((t) => Math.cos(t) * Math.sin(t), 0, Math.PI / 2);
    const ph = simpson((p) => Math.exp(p), 0, 2 * Math.PI);
    expect(examLobeK() * th * ph).toBeCloseTo(1, 10);
  });

  it('marginal pdfs integrate to 1 and CDFs are their integrals', () => {
    expect(simpson(examThetaPdf, 0, Math.PI / 2)).toBeCloseTo(1, 10);
    expect(simpson(examPhiPdf, 0, 2 * Math.PI - 1e-15)).toBeCloseTo(1, 8);
    for (const t of [0.1, 0.5, 1.0, 1.4])
      expect(examThetaCdf(t)).toBeCloseTo(simpson(examThetaPdf, 0, t), 10);
    for (const p of [0.3, 2, 4.5, 6]) expect(examPhiCdf(p)).toBeCloseTo(simpson(examPhiPdf, 0, p), 8);
    expect(examThetaCdf(-1)).toBe(0);
    expect(examThetaCdf(2)).toBe(1);
    expect(examPhiCdf(-1)).toBe(0);
    expect(examPhiCdf(7)).toBe(1);
  });

  it('sin θ = √ξ₁ and cos θ = √(1−ξ₁) match 60-digit references at stress inputs', () => {
    const out = new Float64Array(3);
    for (const xi of STRESS_U) {
      sampleExamLobe(xi, 0, out); // φ = 0: x = sin θ, y = 0
      const sRef = num(m.sqrt(big(xi)));
      const cRef = num(m.sqrt(m.subtract(1, big(xi))));
      if (sRef === 0) expect(out[0]).toBe(0);
      else expect(relErr(out[0], sRef)).toBeLessThan(1.2e-16);
      expect(relErr(out[2], cRef)).toBeLessThan(1.2e-16);
    }
  });

  it('φ = log1p(expm1(2π) ξ₂) has full relative precision at tiny ξ₂ and stays < 2π near 1', () => {
    const out = new Float64Array(3);
    for (const xi of [2 ** -53, 1e-12, 1e-200]) {
      sampleExamLobe(0.5, xi, out);
      const phi = Math.atan2(out[1], out[0]);
      const ref = num(log1pB(m.multiply(cB, big(xi)) as BN));
      expect(relErr(phi, ref)).toBeLessThan(1e-13); // atan2 of the written vector re-derives φ
    }
    sampleExamLobe(0.5, 1 - 2 ** -53, out);
    const phi = Math.atan2(out[1], out[0]) + 2 * Math.PI;
    expect(phi).toBeLessThanOrEqual(2 * Math.PI);
  });

  it('pdf is 0 outside the hemisphere and for NaN; equals k cos θ e^φ inside', () => {
    expect(examLobePdf(0, 0, -1)).toBe(0);
    expect(examLobePdf(1, 0, 0)).toBe(0);
    expect(examLobePdf(0.6, 0, -0.8)).toBe(0);
    expect(examLobePdf(Number.NaN, 0, 1)).toBe(0);
    expect(examLobePdf(0, 0, Number.NaN)).toBe(0);
    const t = 0.7;
    const p = 2.5;
    const v = [Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)];
    expect(examLobePdf(v[0], v[1], v[2])).toBeCloseTo(examLobeK() * Math.cos(t) * Math.exp(p), 12);
    expect(examLobeThetaPhiPdf(t, p)).toBeCloseTo(examLobeK() * Math.cos(t) * Math.sin(t) * Math.exp(p), 12);
    expect(examLobeThetaPhiPdf(-0.1, 1)).toBe(0);
    expect(examLobeThetaPhiPdf(0.1, 7)).toBe(0);
    expect(examThetaPdf(2)).toBe(0);
    expect(examPhiPdf(-0.1)).toBe(0);
    expect(examPhiPdf(Number.NaN)).toBe(0);
  });

  it('pdf(ω) · sin θ equals the product of the marginals (separability, correct Jacobian)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0.01, max: 1.5, noNaN: true }),
        fc.double({ min: 0, max: 6.28, noNaN: true }),
        (t, p) => {
          const lhs = examLobeThetaPhiPdf(t, p);
          const rhs = examThetaPdf(t) * examPhiPdf(p);
          return Math.abs(lhs - rhs) <= 1e-12 * Math.max(1, rhs);
        },
      ),
      { numRuns: 500, seed: 3 },
    );
  });

  it('importance estimate of ∫cos θ dω = π: f/p = e^{-φ}/k, mean within 4σ', () => {
    const rng = new Rng(77);
    const out = [0, 0, 0];
    const n = 100000;
    let s = 0;
    let s2 = 0;
    for (let i = 0; i < n; i++) {
      sampleExamLobe(rng.nextFloat(), rng.nextFloat(), out);
      const w = out[2] / examLobePdf(out[0], out[1], out[2]);
      s += w;
      s2 += w * w;
    }
    const mean = s / n;
    const se = Math.sqrt((s2 / n - mean * mean) / n);
    expect(Math.abs(mean - Math.PI)).toBeLessThan(4 * se);
  });

  describe("the key's inverted Jacobian p(ω)/sin θ", () => {
    it('partial integral ∫_ε^{π/2} cot θ dθ = −ln sin ε matches 60 digits and grows without bound', () => {
      let prev = 0;
      for (const eps of [1, 0.1, 1e-3, 1e-8, 1e-100, 1e-300]) {
        const v = invertedJacobianPartialIntegral(eps);
        const ref = num(m.unaryMinus(m.log(m.sin(big(eps)))));
        expect(relErr(v, ref)).toBeLessThan(1e-15);
        expect(v).toBeGreaterThan(prev);
        prev = v;
      }
      expect(prev).toBeGreaterThan(690); // −ln 1e-300
      expect(invertedJacobianPartialIntegral(0)).toBe(Infinity);
      expect(invertedJacobianPartialIntegral(Math.PI / 2)).toBe(0);
    });
    it('density is finite away from θ = 0, +∞ at 0, 0 outside', () => {
      expect(invertedJacobianDensity(0, 1)).toBe(Infinity);
      expect(invertedJacobianDensity(1e-3, 1)).toBeCloseTo((examLobeK() * Math.E) / Math.tan(1e-3), 8);
      expect(invertedJacobianDensity(-1, 1)).toBe(0);
      expect(invertedJacobianDensity(1, 7)).toBe(0);
    });
  });
});
