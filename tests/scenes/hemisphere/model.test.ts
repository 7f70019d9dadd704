import { describe, expect, it } from 'vitest';
import { computeDrawStats, drawDirections } from '../../../src/scenes/hemisphere/drawStats';
import { exactIntegral } from '../../../src/scenes/hemisphere/integral';
import { invertedJacobianSeries } from '../../../src/scenes/hemisphere/examChecks';
import { lobeFromParams, makeLobe } from '../../../src/scenes/hemisphere/lobe';
import { marginalHistograms } from '../../../src/scenes/hemisphere/sampleCheck';
import { repeatEstimates } from '../../../src/scenes/hemisphere/q2Estimates';
import { tabulateHemisphereDensity, examLobeK } from '../../../src/core/sampling';
import { formatNumber } from '../../../src/core/format';
import { LOBES } from '../../../src/scenes/hemisphere/params';

const cosTheta = (t: number) => Math.cos(t);

function customLobe() {
  const r = tabulateHemisphereDensity((t, p) => Math.cos(t) ** 2 * (2 + Math.cos(p)));
  if (!r.ok) throw new Error(r.message);
  return makeLobe('custom', 8, r.lobe)!;
}

describe('hemisphere scene model', () => {
  it('k of each lobe is its normalization constant', () => {
    expect(makeLobe('exam', 8)!.k).toBe(examLobeK());
    expect(makeLobe('uniform', 8)!.k).toBe(1 / (2 * Math.PI));
    expect(makeLobe('cosine', 8)!.k).toBe(1 / Math.PI);
    expect(makeLobe('phong', 8)!.k).toBe(9 / (2 * Math.PI));
    expect(makeLobe('custom', 8, null)).toBeNull();
    // typed cos²θ (2 + cos φ): ∫ = 2π · 2/3 … → k = 3/(4π)
    expect(Math.abs((customLobe().k * (4 * Math.PI)) / 3 - 1)).toBeLessThan(2e-3);
  });

  it('exact ∫ cos θ dω = π; ∫ 1 dω = 2π; ∫ cos²θ sin φ dω = 0', () => {
    expect(exactIntegral(cosTheta)).toBeCloseTo(Math.PI, 12);
    expect(exactIntegral(() => 1)).toBeCloseTo(2 * Math.PI, 12);
    expect(Math.abs(exactIntegral((t, p) => Math.cos(t) ** 2 * Math.sin(p)))).toBeLessThan(1e-12);
    expect(Number.isNaN(exactIntegral(() => NaN))).toBe(true);
  });

  it('every lobe: χ² passes, estimates agree with the exact integral within 4σ', () => {
    for (const id of LOBES) {
      const lobe = id === 'custom' ? customLobe() : makeLobe(id, 8)!;
      const s = computeDrawStats(lobe, cosTheta, 'independent', 3, 20000);
      expect(s.chi2!.pass, id).toBe(true);
      expect(Math.abs(s.q2.uniform.estimate - Math.PI)).toBeLessThan(4 * s.q2.uniform.stderr);
      expect(Math.abs(s.q2.importance.estimate - Math.PI), id).toBeLessThan(
        4 * s.q2.importance.stderr + 1e-12,
      );
      expect(s.q2.importance.invalid).toBe(0);
    }
  });

  it('cosine lobe with f = cos θ has zero variance: f/p = π exactly per sample', () => {
    const s = computeDrawStats(makeLobe('cosine', 8), cosTheta, 'sobol', 1, 4096);
    expect(s.q2.importance.estimate).toBeCloseTo(Math.PI, 12);
    expect(s.q2.importance.stderr).toBeLessThan(1e-12);
  });

  it('histograms are densities matching the marginals', () => {
    const lobe = makeLobe('exam', 8)!;
    const { dirs } = drawDirections(lobe, 'sobol', 2, 1 << 16);
    const h = marginalHistograms(lobe, dirs, 1 << 16, 36);
    let mass = 0;
    for (let b = 0; b < 36; b++) mass += h.theta.density[b] * h.theta.width;
    expect(mass).toBeCloseTo(1, 12);
    // p(θ) = sin 2θ: bin at centre π/4 ≈ 1
    expect(h.theta.density[18]).toBeGreaterThan(0.95);
    expect(h.phi.curveY[200]).toBeGreaterThan(0); // last curve point inside the half-open support
  });

  it('repeat many times: the mean of independent estimates centres on the integral (Q2(c))', () => {
    const lobe = makeLobe('exam', 8)!;
    const r = repeatEstimates(lobe, cosTheta, 'independent', 7, 400, 64);
    for (const arr of [r.uniform, r.importance]) {
      let s = 0;
      let s2 = 0;
      for (const x of arr) {
        s += x;
        s2 += x * x;
      }
      const mean = s / arr.length;
      const se = Math.sqrt((s2 / arr.length - mean * mean) / arr.length);
      expect(Math.abs(mean - Math.PI)).toBeLessThan(4 * se);
    }
  });

  it('inverted Jacobian: partial integrals grow without bound, always finite', () => {
    const { eps, partial } = invertedJacobianSeries(40);
    for (let i = 1; i < 40; i++) {
      expect(eps[i]).toBeLessThan(eps[i - 1]);
      expect(partial[i]).toBeGreaterThan(partial[i - 1]);
      expect(Number.isFinite(partial[i])).toBe(true);
    }
    expect(partial[39]).toBeGreaterThan(34); // −ln 1e-15 ≈ 34.5
  });

  it('no lobe (inverted Jacobian or invalid typed density): no χ², importance estimate off, uniform still valid', () => {
    const s = computeDrawStats(null, cosTheta, 'independent', 1, 5000);
    expect(s.chi2).toBeNull();
    expect(s.hist).toBeNull();
    expect(Number.isNaN(s.q2.importance.estimate)).toBe(true);
    expect(Math.abs(s.q2.uniform.estimate - Math.PI)).toBeLessThan(4 * s.q2.uniform.stderr);
    expect(s.exact).toBeCloseTo(Math.PI, 12);
  });

  it('same (lobe, set, seed, n) → same numbers (reproducible links)', () => {
    const a = computeDrawStats(makeLobe('exam', 8), cosTheta, 'halton', 42, 3000);
    const b = computeDrawStats(makeLobe('exam', 8), cosTheta, 'halton', 42, 3000);
    expect(a.chi2!.pValue).toBe(b.chi2!.pValue);
    expect(a.q2.importance.estimate).toBe(b.q2.importance.estimate);
    const c = computeDrawStats(makeLobe('exam', 8), cosTheta, 'halton', 43, 3000);
    expect(c.q2.importance.estimate).not.toBe(a.q2.importance.estimate);
  });
});

describe('the typed density’s k', () => {
  it('is 1/∫ p dω to every digit the readout prints, not the table’s approximation', () => {
    // p ∝ cos³θ e^{φ/2}: ∫ p dω = ¼ · 2(e^π − 1), so k = 2/(e^π − 1)
    const f = (t: number, p: number) => Math.cos(t) ** 3 * Math.exp(0.5 * p);
    const exact = 2 / Math.expm1(Math.PI);
    const { lobe } = lobeFromParams('custom', 1, f);
    expect(lobe).not.toBeNull();
    expect(lobe!.kDigits).toBe(8);
    expect(formatNumber(lobe!.k, lobe!.kDigits)).toBe(formatNumber(exact, lobe!.kDigits));
    expect(Math.abs(lobe!.k / exact - 1)).toBeLessThan(1e-10);
  });
  it('built-in lobes print k to 8 digits from their closed forms', () => {
    expect(makeLobe('exam', 1)!.kDigits).toBe(8);
    expect(makeLobe('exam', 1)!.k).toBe(examLobeK());
  });
});
