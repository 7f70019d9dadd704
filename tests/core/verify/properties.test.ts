import { describe, it } from 'vitest';
import fc from 'fast-check';
import { chi2Test, hemisphereChi2, planarChi2, sidakAlpha } from '../../../src/core/verify';

describe('χ² machinery: properties over whole input ranges', () => {
  it('chi2Test: statistic ≥ 0, 0 ≤ p ≤ 1, dof < bins, and observed = expected always passes', () => {
    fc.assert(
      fc.property(
        fc.array(fc.double({ min: 0, max: 1e6, noNaN: true }), { minLength: 3, maxLength: 60 }),
        fc.double({ min: 0.5, max: 20, noNaN: true }),
        (e, minExpected) => {
          const r = chi2Test(e, e, { minExpected });
          if (!(r.statistic >= 0 && r.dof <= e.length - 1)) return false;
          // with enough usable bins the perfect fit must pass; otherwise p is NaN and the result says why
          return r.dof >= 1
            ? r.pass && r.statistic === 0 && r.pValue === 1
            : !r.pass && Number.isNaN(r.pValue) && typeof r.note === 'string';
        },
      ),
    );
  });

  it('chi2Test: any observed counts give a finite statistic and a p-value in [0, 1]', () => {
    fc.assert(
      fc.property(
        fc.array(fc.tuple(fc.nat(1000), fc.double({ min: 0.01, max: 1000, noNaN: true })), {
          minLength: 2,
          maxLength: 40,
        }),
        (pairs) => {
          const r = chi2Test(
            pairs.map((p) => p[0]),
            pairs.map((p) => p[1]),
          );
          if (r.dof < 1) return Number.isNaN(r.pValue) && !r.pass;
          return (
            Number.isFinite(r.statistic) &&
            r.pValue >= 0 &&
            r.pValue <= 1 &&
            r.pass === r.pValue >= r.sidakAlpha
          );
        },
      ),
    );
  });

  it('sidakAlpha decreases with the number of tests', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 1e-9, max: 0.5, noNaN: true }),
        fc.integer({ min: 1, max: 1e5 }),
        (a, m) => sidakAlpha(a, m + 1) < sidakAlpha(a, m),
      ),
    );
  });

  it('hemisphere expected counts integrate a normalized Phong lobe to N for any exponent in [0, 60]', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 60, noNaN: true }),
        fc.integer({ min: 1, max: 8 }),
        fc.integer({ min: 1, max: 16 }),
        (n, nc, np) => {
          const pdf = (_x: number, _y: number, z: number) =>
            z > 0 ? ((n + 1) / (2 * Math.PI)) * Math.pow(z, n) : 0;
          // one sample: the expected counts are the bin integrals of the pdf
          const r = hemisphereChi2(new Float64Array([0, 0, 1]), 1, pdf, { cosThetaBins: nc, phiBins: np });
          const total = r.expected.reduce((a, b) => a + b, 0);
          // exponents near 0 put a kink (c^n, infinite slope) at cos θ = 0; 1e-7 is far below χ² noise
          return Math.abs(total - 1) < 1e-7;
        },
      ),
      { numRuns: 30 },
    );
  });

  it('planar expected counts sum to N for a uniform density on any rectangle', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -100, max: 100, noNaN: true }),
        fc.double({ min: 1e-3, max: 100, noNaN: true }),
        fc.double({ min: -100, max: 100, noNaN: true }),
        fc.double({ min: 1e-3, max: 100, noNaN: true }),
        (x0, w, y0, h) => {
          const domain = { x0, x1: x0 + w, y0, y1: y0 + h };
          const pts = new Float64Array([x0 + w / 2, y0 + h / 2]);
          const r = planarChi2(pts, 1, () => 1 / (w * h), { domain, xBins: 5, yBins: 4 });
          const s = r.expected.reduce((a, b) => a + b, 0);
          return Math.abs(s - 1) < 1e-9 && r.observed.reduce((a, b) => a + b, 0) === 1 && r.outside === 0;
        },
      ),
      { numRuns: 50 },
    );
  });
});
