import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { tabulateHemisphereDensity, type TabulatedHemisphere } from '../../../src/core/sampling/tabulatedHemisphere';
import { examLobeK } from '../../../src/core/sampling/examLobe';
import { hemisphereChi2 } from '../../../src/core/verify';
import { fillSequence2D } from '../../../src/core/random';
import { STRESS_PAIRS, norm3 } from './stress';

function ok(p: (t: number, f: number) => number): TabulatedHemisphere {
  const r = tabulateHemisphereDensity(p);
  if (!r.ok) throw new Error(r.message);
  return r.lobe;
}
const unit = fc.double({ min: 0, max: 1, maxExcluded: true, noNaN: true });

describe('tabulated hemisphere density (typed lobe)', () => {
  it('cos θ: k ≈ 1/π; exam density: k ≈ 2/(e^{2π}−1) (midpoint table, 0.1 %)', () => {
    expect(Math.abs(ok((t) => Math.cos(t)).k * Math.PI - 1)).toBeLessThan(1e-3);
    expect(Math.abs(ok((t, f) => Math.cos(t) * Math.exp(f)).k / examLobeK() - 1)).toBeLessThan(1e-3);
  });

  it('pdf integrates to 1 over the hemisphere and is 0 below it', () => {
    const lobe = ok((t, f) => 1 + Math.sin(3 * f) * Math.sin(t) ** 2);
    let s = 0;
    const n = 128; // a multiple of the table's 64 × 128 cells: the midpoint sum is exact
    for (let i = 0; i < n; i++)
      for (let j = 0; j < 2 * n; j++) {
        const z = (i + 0.5) / n;
        const phi = ((j + 0.5) / (2 * n)) * 2 * Math.PI;
        const r = Math.sqrt(1 - z * z);
        s += lobe.pdf(r * Math.cos(phi), r * Math.sin(phi), z);
      }
    expect((s * 2 * Math.PI) / (2 * n * n)).toBeCloseTo(1, 10);
    expect(lobe.pdf(0, 0, -0.5)).toBe(0);
    expect(lobe.pdf(Number.NaN, 0, 0.5)).toBe(0);
  });

  it('stress inputs: finite unit vectors with z ≥ 0; batch equals scalar', () => {
    const lobe = ok((t, f) => Math.cos(t) * Math.exp(f));
    const out = new Float64Array(3);
    const u = new Float64Array(2 * STRESS_PAIRS.length);
    STRESS_PAIRS.forEach(([a, b], i) => {
      u[2 * i] = a;
      u[2 * i + 1] = b;
      lobe.sample(a, b, out);
      expect(out.every(Number.isFinite)).toBe(true);
      expect(out[2]).toBeGreaterThanOrEqual(0);
      expect(Math.abs(norm3(out) - 1)).toBeLessThan(1e-15);
    });
    const batch = lobe.sampleBatch(u, new Float64Array(3 * STRESS_PAIRS.length), STRESS_PAIRS.length);
    STRESS_PAIRS.forEach(([a, b], i) => {
      lobe.sample(a, b, out);
      for (let c = 0; c < 3; c++) expect(batch[3 * i + c]).toBeCloseTo(out[c], 14);
    });
  });

  it('round trip invert(sample(ξ)) ≈ ξ (property)', () => {
    const lobe = ok((t, f) => Math.cos(t) * (2 + Math.cos(f)));
    const out = [0, 0, 0];
    fc.assert(
      fc.property(unit, unit, (a, b) => {
        lobe.sample(a, b, out);
        const [u1, u2] = lobe.invert(out[0], out[1], out[2]);
        return Math.abs(u1 - a) < 1e-9 && Math.abs(u2 - b) < 1e-7;
      }),
      { numRuns: 2000, seed: 17 },
    );
  });

  it('χ² accepts the tabulated sampler against its own pdf (non-separable density)', () => {
    const lobe = ok((t, f) => Math.cos(t) ** 2 * (1.5 + Math.sin(2 * f + 3 * t)));
    const N = 100_000;
    const u = fillSequence2D('independent', 5, N, new Float64Array(2 * N));
    const dirs = lobe.sampleBatch(u, new Float64Array(3 * N), N);
    const r = hemisphereChi2(dirs, N, (x, y, z) => lobe.pdf(x, y, z));
    expect(r.pass).toBe(true);
  });

  it('rejects negative, non-finite and all-zero densities with messages', () => {
    const neg = tabulateHemisphereDensity((t) => Math.cos(t) - 0.5);
    expect(neg.ok).toBe(false);
    if (!neg.ok) {
      expect(neg.kind).toBe('negative');
      expect(neg.message).toMatch(/negative/);
    }
    const nan = tabulateHemisphereDensity((t) => Math.sqrt(1 - 2 * t));
    expect(nan.ok || nan.kind).toBe('nonfinite');
    const zero = tabulateHemisphereDensity(() => 0);
    expect(zero.ok || zero.kind).toBe('zero');
    const thrower = tabulateHemisphereDensity(() => {
      throw new Error('boom');
    });
    expect(thrower.ok || thrower.kind).toBe('error');
  });

  it("rejects non-integrable densities: the key's cot θ variant per solid angle, 1/cos θ, 1/φ, 1/(2π−φ)", () => {
    const cases: [string, (t: number, f: number) => number][] = [
      ['pole', (t, f) => (Math.cos(t) / Math.sin(t) ** 2) * Math.exp(f)],
      ['horizon', (t) => 1 / Math.cos(t)],
      ['φ → 0', (_t, f) => 1 / f],
      ['φ → 2π', (_t, f) => 1 / (2 * Math.PI - f)],
    ];
    for (const [where, p] of cases) {
      const r = tabulateHemisphereDensity(p);
      expect(r.ok).toBe(false);
      if (!r.ok) {
        expect(r.kind).toBe('divergent');
        expect(r.message).toContain(where);
      }
    }
  });

  it('accepts integrable singularities (1/θ at the pole, 1/√φ)', () => {
    expect(tabulateHemisphereDensity((t) => 1 / t).ok).toBe(true);
    expect(tabulateHemisphereDensity((_t, f) => 1 / Math.sqrt(f)).ok).toBe(true);
  });

  it('warns when the table cannot resolve a sharp lobe', () => {
    const r = tabulateHemisphereDensity((t) => Math.cos(t) ** 2000);
    expect(r.ok).toBe(true);
    if (r.ok) expect(r.warning).toMatch(/refined/);
  });
});
