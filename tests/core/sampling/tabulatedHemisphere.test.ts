import { describe, expect, it } from 'vitest';
import {
  tabulateHemisphereDensity,
  type TabulatedHemisphere,
} from '../../../src/core/sampling/tabulatedHemisphere';
import { examLobeK } from '../../../src/core/sampling/examLobe';

function ok(p: (t: number, f: number) => number): TabulatedHemisphere {
  const r = tabulateHemisphereDensity(p);
  if (!r.ok) throw new Error(r.message);
  return r.lobe;
}

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
