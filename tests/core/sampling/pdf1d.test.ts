import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { create, all } from 'mathjs';
import {
  invertLinear1DSample,
  invertSquare1DSample,
  invertUniform1DSample,
  linear1DPdf,
  linearPdf1D,
  sampleLinear1D,
  sampleSquare1D,
  sampleUniform1D,
  square1DPdf,
  squarePdf1D,
  uniform1DPdf,
  uniformPdf1D,
  customPdf1D,
  piecewiseConstantPdf1D,
  proportionalPdf1D,
  type Pdf1D,
} from '../../../src/core/sampling/pdf1d';
import { integrate1D } from '../../../src/core/verify/integrate1d';
import { chi2Test } from '../../../src/core/verify/chi2';
import { Rng } from '../../../src/core/random';

const TINY = 2 ** -53;
const NEAR_ONE = 1 - 2 ** -53;
const STRESS_U = [0, TINY, 0.5, NEAR_ONE];
const unit = fc.double({ min: 0, max: 1, maxExcluded: true, noNaN: true });
const M = create(all, { number: 'BigNumber', precision: 60 });

/** χ² of `sampler` against the density `pdf` on [a, b]: expected counts by quadrature of the pdf. */
function chi2Of(
  sampler: (u: number) => number,
  pdf: (x: number) => number,
  a: number,
  b: number,
  seed: number,
  n = 40000,
  bins = 40,
) {
  const rng = new Rng(seed);
  const obs = new Float64Array(bins);
  for (let i = 0; i < n; i++) {
    const x = sampler(rng.nextFloat());
    obs[Math.min(bins - 1, Math.floor(((x - a) / (b - a)) * bins))]++;
  }
  const exp = new Float64Array(bins);
  for (let k = 0; k < bins; k++)
    exp[k] = n * integrate1D(pdf, a + ((b - a) * k) / bins, a + ((b - a) * (k + 1)) / bins).value;
  return chi2Test(obs, exp, { alpha: 0.01, tests: 4 });
}

const cases: { name: string; pdf: Pdf1D }[] = [
  { name: 'uniform', pdf: uniformPdf1D(-1, 3) },
  { name: 'linear 4→16', pdf: linearPdf1D(0, 2, 4, 16) },
  { name: 'linear 0→1', pdf: linearPdf1D(0, 1, 0, 1) },
  { name: 'linear 5→0', pdf: linearPdf1D(-2, 0.5, 5, 0) },
  { name: 'square c=2 (exam)', pdf: squarePdf1D(0, 2, 2) },
  { name: 'square across the zero of x + c', pdf: squarePdf1D(-3, 1, 2) },
  { name: 'tabulated ∝ |sin x| on [0, 5] (sign change)', pdf: okPdf(proportionalPdf1D(Math.sin, 0, 5, 512)) },
  { name: 'custom exp(x) on [-1, 2]', pdf: okPdf(customPdf1D(Math.exp, -1, 2, undefined, 256)) },
  { name: 'piecewise with empty bins', pdf: piecewiseConstantPdf1D([0, 0, 1, 0, 3, 0, 0], 1, 8) },
];

function okPdf(r: ReturnType<typeof customPdf1D>): Pdf1D {
  if (!r.ok) throw new Error(r.message);
  return r.pdf;
}

describe('1D pdfs: shared properties', () => {
  for (const { name, pdf } of cases) {
    it(`${name}: integrates to 1, 0 outside, stress ξ in range, round trip, χ²`, () => {
      const { a, b } = pdf;
      expect(integrate1D((x) => pdf.pdf(x), a, b).value).toBeCloseTo(1, 13);
      expect(pdf.pdf(a - 1e-9)).toBe(0);
      expect(pdf.pdf(b + 1e-9)).toBe(0);
      expect(pdf.pdf(NaN)).toBe(0);
      for (const u of STRESS_U) {
        const x = pdf.sample(u);
        expect(Number.isFinite(x)).toBe(true);
        expect(x).toBeGreaterThanOrEqual(a);
        expect(x).toBeLessThanOrEqual(b);
        expect(Number.isNaN(pdf.pdf(x))).toBe(false);
        expect(Math.abs(pdf.invert(x) - u)).toBeLessThan(1e-12);
      }
      // the ends of the support map to the ends of [0, 1) (empty end bins move the support inwards)
      if (pdf.pdf(a) > 0) expect(pdf.sample(0)).toBeCloseTo(a, 14);
      if (pdf.pdf(b) > 0) expect(pdf.sample(NEAR_ONE)).toBeCloseTo(b, 7);
      expect(pdf.pdf(pdf.sample(TINY))).toBeGreaterThan(0);
      expect(pdf.pdf(pdf.sample(NEAR_ONE))).toBeGreaterThan(0);
      fc.assert(
        fc.property(unit, (u) => {
          const x = pdf.sample(u);
          expect(x).toBeGreaterThanOrEqual(a);
          expect(x).toBeLessThanOrEqual(b);
          expect(Math.abs(pdf.invert(x) - u)).toBeLessThan(1e-11);
        }),
      );
      // batched = scalar
      const u = Float64Array.from([0, TINY, 0.1, 0.5, 0.9, NEAR_ONE]);
      const x = new Float64Array(6);
      const p = new Float64Array(6);
      pdf.sampleBatch(u, x, p, 0, 6);
      for (let i = 0; i < 6; i++) {
        expect(x[i]).toBeCloseTo(pdf.sample(u[i]), 13);
        expect(p[i]).toBeCloseTo(pdf.pdf(x[i]), 12);
      }
      const r = chi2Of(
        (v) => pdf.sample(v),
        (v) => pdf.pdf(v),
        a,
        b,
        1234,
      );
      expect(r.pass, `χ² p = ${r.pValue}`).toBe(true);
    });
  }
});

describe('closed forms', () => {
  it('uniform triple', () => {
    expect(sampleUniform1D(0.25, 2, 6)).toBe(3);
    expect(uniform1DPdf(4, 2, 6)).toBe(0.25);
    expect(invertUniform1DSample(5, 2, 6)).toBe(0.75);
  });

  it('linear ramp: density at the ends and the CDF in BigNumber', () => {
    expect(linear1DPdf(0, 0, 2, 4, 16)).toBeCloseTo((2 * 4) / (20 * 2), 15);
    expect(linear1DPdf(2, 0, 2, 4, 16)).toBeCloseTo((2 * 16) / (20 * 2), 15);
    // CDF of the ramp: (w0 t + (w1 − w0) t²/2) / ((w0 + w1)/2); check invert at t = 0.3 in 60 digits
    const t = M.bignumber(0.3);
    const ref = M.number(M.divide(M.add(M.multiply(4, t), M.multiply(6, M.multiply(t, t))), 10) as never);
    expect(Math.abs(invertLinear1DSample(0.6, 0, 2, 4, 16) - ref)).toBeLessThan(1e-16);
    // a zero end: tiny u stays tiny and finite (no 0/0)
    expect(sampleLinear1D(TINY, 0, 1, 0, 1)).toBeGreaterThan(0);
    expect(sampleLinear1D(0, 0, 1, 0, 1)).toBe(0);
  });

  it('square: exam pdf (3/56)(x + 2)² and the cube-root inverse against BigNumber', () => {
    for (const x of [0, 0.54, 1.16, 1.26, 1.98, 2]) {
      expect(square1DPdf(x, 0, 2, 2)).toBeCloseTo((3 / 56) * (x + 2) ** 2, 15);
    }
    for (const u of [TINY, 1e-10, 0.5, NEAR_ONE]) {
      const ub = M.bignumber(u);
      const ref = M.number(M.subtract(M.cbrt(M.add(8, M.multiply(56, ub)) as never), 2) as never);
      expect(Math.abs(sampleSquare1D(u, 0, 2, 2) - ref)).toBeLessThanOrEqual(
        4e-16 * Math.max(1, Math.abs(ref)),
      );
    }
    // tiny u: CDF inverse stays accurate relative to the offset from a (u ≈ 12 x/56 ·… near x = 0)
    const x = 1e-12;
    const uRef = M.number(M.divide(M.subtract(M.pow(M.bignumber(2 + x), 3), 8), 56) as never);
    expect(Math.abs(invertSquare1DSample(x, 0, 2, 2) - uRef) / uRef).toBeLessThan(1e-3);
    expect(Math.abs(invertSquare1DSample(1, 0, 2, 2) - 19 / 56)).toBeLessThan(1e-16);
  });

  it('linearPdf1D rejects invalid weights with a clear error', () => {
    expect(() => linearPdf1D(0, 1, 0, 0)).toThrow(/not both 0/);
    expect(() => linearPdf1D(0, 1, -1, 2)).toThrow(/≥ 0/);
  });
});

describe('χ² rejects deliberately broken samplers', () => {
  it('linear without the square root', () => {
    const broken = (u: number) => 2 * ((u * 20) / (4 + ((1 - u) * 16 + u * 256)));
    const r = chi2Of(broken, (x) => linear1DPdf(x, 0, 2, 4, 16), 0, 2, 5);
    expect(r.pass).toBe(false);
  });
  it('square with √ instead of ∛ (wrong exponent)', () => {
    const broken = (u: number) => Math.min(2, Math.max(0, Math.sqrt(4 + u * 12) - 2));
    const r = chi2Of(broken, (x) => square1DPdf(x, 0, 2, 2), 0, 2, 6);
    expect(r.pass).toBe(false);
  });
});

describe('typed densities (custom, proportional to f)', () => {
  it('normalizes numerically: Z and the exact normalized density', () => {
    const r = customPdf1D((x) => (x + 2) ** 2, 0, 2);
    expect(r.ok).toBe(true);
    if (!r.ok) return;
    expect(r.norm).toBeCloseTo(56 / 3, 12);
    expect(r.density(1.16)).toBeCloseTo((3 / 56) * 3.16 ** 2, 14);
    expect(r.density(-0.1)).toBe(0);
    // every table bin carries the exact mass of p: the CDF at bin edges is exact
    const edge = 0 + 2 * (1000 / 4096);
    const exactCdf = ((edge + 2) ** 3 - 8) / 56;
    expect(Math.abs(r.pdf.invert(edge) - exactCdf)).toBeLessThan(1e-13);
    // the tabulated density is close to the true one (bin width 2/4096)
    expect(Math.abs(r.pdf.pdf(1.16) / r.density(1.16) - 1)).toBeLessThan(2e-3);
  });

  it('proportional to f gives f/q ≈ ∫|f| for every sample (near-zero variance)', () => {
    const f = (x: number) => Math.exp(-x) * (2 + Math.cos(3 * x));
    const r = proportionalPdf1D(f, 0, 3);
    if (!r.ok) throw new Error(r.message);
    const u = Float64Array.from({ length: 64 }, (_, i) => (i + 0.5) / 64);
    const x = new Float64Array(64);
    const p = new Float64Array(64);
    r.pdf.sampleBatch(u, x, p, 0, 64);
    for (let i = 0; i < 64; i++) expect(Math.abs(f(x[i]) / p[i] / r.norm - 1)).toBeLessThan(5e-3);
  });

  it('rejects bad pdfs with clear messages', () => {
    const neg = customPdf1D((x) => x - 1, 0, 2);
    expect(neg.ok).toBe(false);
    if (!neg.ok) {
      expect(neg.kind).toBe('negative');
      expect(neg.message).toMatch(/cannot be negative/);
      expect(neg.x!).toBeLessThan(1);
    }
    const zero = customPdf1D(
      (x) => (x < 1 ? 0 : 1),
      0,
      2,
      (x) => (x + 2) ** 2,
    );
    expect(zero.ok).toBe(false);
    if (!zero.ok) {
      expect(zero.kind).toBe('zero-where-f-nonzero');
      expect(zero.message).toMatch(/biased/);
    }
    // zero where f is zero too is fine
    expect(
      customPdf1D(
        (x) => (x < 1 ? 0 : 1),
        0,
        2,
        (x) => (x < 1 ? 0 : x),
      ).ok,
    ).toBe(true);
    const div = customPdf1D((x) => 1 / x, 0, 1);
    expect(div.ok).toBe(false);
    if (!div.ok) expect(div.kind).toBe('not-normalizable');
    const nan = customPdf1D((x) => Math.sqrt(x - 1), 0, 2);
    expect(nan.ok).toBe(false);
    if (!nan.ok) expect(nan.kind).toBe('not-finite');
    const allZero = customPdf1D(() => 0, 0, 1);
    expect(allZero.ok).toBe(false);
    if (!allZero.ok) expect(allZero.kind).toBe('zero');
    const fzero = proportionalPdf1D(() => 0, 0, 1);
    expect(fzero.ok).toBe(false);
    // integrable singularity: 1/√x is a fine (unnormalized) density
    const sing = customPdf1D((x) => 1 / Math.sqrt(x), 0, 1);
    expect(sing.ok).toBe(true);
    if (sing.ok) expect(sing.norm).toBeCloseTo(2, 8);
  });
});
