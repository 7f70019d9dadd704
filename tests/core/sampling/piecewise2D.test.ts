import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { PiecewiseConstant2D, DensityError } from '../../../src/core/sampling';
import { Rng } from '../../../src/core/random';
import { planarChi2 } from '../../../src/core/verify';

const STRESS = [0, 2 ** -53, 0.5, 1 - 2 ** -53];
const domain = { u0: 0, u1: 2, v0: -1, v1: 1 };
// 4 columns (u) × 3 rows (v), row-major; the middle row is empty
const f = [1, 2, 3, 4, 0, 0, 0, 0, 5, 0, 1, 2];
const d = new PiecewiseConstant2D(f, 4, 3, domain);

describe('PiecewiseConstant2D', () => {
  it('has marginal = row integrals and a pdf that integrates to 1', () => {
    const cell = (2 / 4) * (2 / 3);
    expect(d.integral).toBeCloseTo(18 * cell, 14);
    expect(d.marginal.count).toBe(3);
    expect(d.conditional(1).integral).toBe(0);
    expect(d.conditional(0).pdf(0.25)).toBeCloseTo(1 / (10 * 0.5), 14); // p(u | row 0) = f / ∫ f du
    expect(d.marginal.pdf(-0.9)).toBeCloseTo(10 / 18 / (2 / 3), 14); // row 0 carries 10/18 of the mass
    let s = 0;
    for (let iv = 0; iv < 3; iv++)
      for (let iu = 0; iu < 4; iu++) s += d.pdf(0.5 * (iu + 0.5), -1 + (2 / 3) * (iv + 0.5)) * cell;
    expect(s).toBeCloseTo(1, 14);
    expect(d.pdf(-0.1, 0)).toBe(0);
    expect(d.pdf(1, 1.5)).toBe(0);
    expect(d.pdf(NaN, 0)).toBe(0);
  });

  it('rejects bad tables', () => {
    expect(() => new PiecewiseConstant2D([1, 2, 3], 2, 2)).toThrow(RangeError);
    expect(() => new PiecewiseConstant2D([1, -2, 3, 4], 2, 2)).toThrow(DensityError);
    expect(() => new PiecewiseConstant2D([0, 0, 0, 0], 2, 2)).toThrow(/zero everywhere/);
  });

  it('samples are in the domain with pdf = pdf(u, v) > 0 for stress ξ, never in empty cells', () => {
    for (const a of STRESS) {
      for (const b of STRESS) {
        const s = d.sample(a, b);
        expect(s.u >= 0 && s.u <= 2 && s.v >= -1 && s.v <= 1).toBe(true);
        expect(s.pdf).toBeGreaterThan(0);
        expect(s.pdf).toBeCloseTo(d.pdf(s.u, s.v), 12);
      }
    }
  });

  it('invert(sample(ξ)) = ξ (property)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 1 - 2 ** -53, noNaN: true }),
        fc.double({ min: 0, max: 1 - 2 ** -53, noNaN: true }),
        (a, b) => {
          const s = d.sample(a, b);
          const r = d.invert(s.u, s.v);
          return Math.abs(r.u1 - a) < 1e-12 && Math.abs(r.u2 - b) < 1e-12;
        },
      ),
    );
  });

  it('passes a planar χ² test against its own pdf and fails against a perturbed one', () => {
    const rng = new Rng(21);
    const n = 50000;
    const pts = new Float64Array(2 * n);
    for (let i = 0; i < n; i++) {
      const s = d.sample(rng.nextFloat(), rng.nextFloat());
      pts[2 * i] = s.u;
      pts[2 * i + 1] = s.v;
    }
    const opts = { domain: { x0: 0, x1: 2, y0: -1, y1: 1 }, xBins: 8, yBins: 6 };
    expect(planarChi2(pts, n, (u, v) => d.pdf(u, v), opts).pass).toBe(true);
    const g = f.slice();
    g[0] = 2;
    g[3] = 3;
    const e = new PiecewiseConstant2D(g, 4, 3, domain);
    expect(planarChi2(pts, n, (u, v) => e.pdf(u, v), opts).pass).toBe(false);
  });
});
