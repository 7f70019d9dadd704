import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { all, create } from 'mathjs';
import {
  centredRectangleSolidAngle,
  parallelogramSolidAngle,
  patchSolidAngleApprox,
  triangleSolidAngle,
  triangleSolidAngleEdges,
} from '../../../src/core/geometry/solidAngle';

const M = create(all, { number: 'BigNumber', precision: 64 });
const B = (x: number) => M.bignumber(x);

/**
 * Closed form for an axis-aligned rectangle [x0, x1] × [y0, y1] in the plane z = d (viewpoint at
 * the origin), by inclusion–exclusion of the corner formula F(a, b) = atan(a b / (d √(a² + b² + d²)))
 * (the solid angle of [0, a] × [0, b], signed). Evaluated in 64-digit BigNumber arithmetic.
 */
function rectOmegaBig(x0: number, x1: number, y0: number, y1: number, d: number): number {
  const D = B(Math.abs(d));
  const F = (a: number, b: number) => {
    const A = B(a),
      Bb = B(b);
    const s = A.times(A).plus(Bb.times(Bb)).plus(D.times(D)).sqrt();
    return A.times(Bb).div(D.times(s)).atan();
  };
  return F(x1, y1).minus(F(x0, y1)).minus(F(x1, y0)).plus(F(x0, y0)).toNumber();
}

const rectOmega = (x0: number, x1: number, y0: number, y1: number, d: number) =>
  parallelogramSolidAngle(x0, y0, d, x1 - x0, 0, 0, 0, y1 - y0, 0);

describe('triangle solid angle (Van Oosterom–Strackee)', () => {
  it('an octant triangle subtends π/2', () => {
    expect(triangleSolidAngle([1, 0, 0], [0, 1, 0], [0, 0, 1])).toBeCloseTo(Math.PI / 2, 14);
  });
  it('is 0 for a degenerate triangle and for a viewpoint in its plane', () => {
    expect(triangleSolidAngle([1, 0, 0], [2, 0, 0], [3, 0, 0])).toBe(0);
    expect(triangleSolidAngleEdges(1, 1, 0, 1, 0, 0, 0, 1, 0)).toBe(0);
  });
  it('does not depend on the winding', () => {
    const a = [0.3, -0.2, 1.5] as const,
      b = [1.1, 0.4, 2] as const,
      c = [-0.5, 0.9, 1.2] as const;
    expect(triangleSolidAngle(a, b, c)).toBeCloseTo(triangleSolidAngle(a, c, b), 15);
  });
});

describe('rectangle solid angle', () => {
  it('matches the centred closed form 4 asin(wh/√((w²+4d²)(h²+4d²))) (BigNumber)', () => {
    for (const [w, h, d] of [
      [1, 1, 2],
      [2, 0.5, 0.1],
      [1, 1, 1e-6],
      [3, 7, 100],
    ] as const) {
      const W = B(w),
        H = B(h),
        D4 = B(d).times(B(d)).times(4);
      const ref = W.times(H)
        .div(W.times(W).plus(D4).times(H.times(H).plus(D4)).sqrt())
        .asin()
        .times(4)
        .toNumber();
      const got = rectOmega(-w / 2, w / 2, -h / 2, h / 2, d);
      expect(Math.abs(got - ref) / ref).toBeLessThan(1e-13);
      expect(Math.abs(centredRectangleSolidAngle(w, h, d) - ref) / ref).toBeLessThan(1e-13);
    }
  });
  it('matches inclusion–exclusion of the corner formula off axis, either side of the plane', () => {
    const cases = [
      [0.2, 1.7, -0.4, 0.9, 1.3],
      [2, 3, 5, 6, 0.5],
      [-1, 1, -1, 1, -2],
      [10, 10.5, -3, -2.2, 0.01],
    ] as const;
    for (const [x0, x1, y0, y1, d] of cases) {
      const ref = Math.abs(rectOmegaBig(x0, x1, y0, y1, d));
      const got = rectOmega(x0, x1, y0, y1, d);
      expect(Math.abs(got - ref) / ref).toBeLessThan(1e-12);
    }
  });
  it('stays accurate for tiny and distant lights (D = 1e4 … 1e8 × size), against BigNumber', () => {
    for (const D of [1e4, 1e6, 1e8]) {
      // Off-axis, so the light is also seen at a slant: ref by the BigNumber corner formula.
      const x0 = 0.3 * D,
        y0 = -0.2 * D;
      const ref = rectOmegaBig(x0, x0 + 1, y0, y0 + 0.5, D);
      const got = rectOmega(x0, x0 + 1, y0, y0 + 0.5, D);
      expect(ref).toBeGreaterThan(0);
      expect(Math.abs(got - ref) / ref).toBeLessThan(1e-10);
      // And the small-patch formula A cos θ_l / r² agrees to O((size/D)²).
      const cx = x0 + 0.5,
        cy = y0 + 0.25;
      const r = Math.hypot(cx, cy, D);
      const approx = patchSolidAngleApprox(0.5, D / r, r);
      expect(Math.abs(approx - ref) / ref).toBeLessThan(10 / (D * D) + 1e-12);
    }
  });
  it('a naive a·(b×c) would lose digits here: the edge form does not (1e8 on-axis, rel. 1e-12)', () => {
    const d = 1e8;
    const ref = centredRectangleSolidAngle(1, 1, d); // closed form: 4 asin(1/(1+4d²)) ≈ 1/d²
    expect(Math.abs(rectOmega(-0.5, 0.5, -0.5, 0.5, d) - ref) / ref).toBeLessThan(1e-12);
    expect(Math.abs(ref - 1 / (d * d)) * d * d).toBeLessThan(1e-12);
  });
  it('is 0 for a zero-size rectangle and for a viewpoint in the plane', () => {
    expect(parallelogramSolidAngle(1, 1, 1, 0, 0, 0, 0, 1, 0)).toBe(0);
    expect(parallelogramSolidAngle(-0.5, -0.5, 0, 1, 0, 0, 0, 1, 0)).toBe(0);
  });
  it('property: Ω ∈ [0, 2π], and splitting a rectangle in two adds up', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -5, max: 5, noNaN: true }),
        fc.double({ min: -5, max: 5, noNaN: true }),
        fc.double({ min: 0.01, max: 4, noNaN: true }),
        fc.double({ min: 0.01, max: 4, noNaN: true }),
        fc.double({ min: 0.01, max: 5, noNaN: true }),
        fc.double({ min: 0.05, max: 0.95, noNaN: true }),
        (x0, y0, w, h, d, split) => {
          const whole = rectOmega(x0, x0 + w, y0, y0 + h, d);
          const a = rectOmega(x0, x0 + split * w, y0, y0 + h, d);
          const b = rectOmega(x0 + split * w, x0 + w, y0, y0 + h, d);
          expect(whole).toBeGreaterThanOrEqual(0);
          expect(whole).toBeLessThanOrEqual(2 * Math.PI);
          expect(Math.abs(a + b - whole)).toBeLessThan(1e-12 * Math.max(1, whole));
        },
      ),
      { seed: 6, numRuns: 300 },
    );
  });
});

describe('Q6(a): dω = dA cos θ_l / r² in the limit', () => {
  it('the relative error of the patch formula falls like size² as the patch shrinks', () => {
    // A square patch tilted 40° about x, centred at (0.7, −0.3, 2) relative to the viewpoint.
    const t = (40 * Math.PI) / 180;
    const ex = [1, 0, 0],
      ey = [0, Math.cos(t), Math.sin(t)];
    const n = [0, Math.sin(t), -Math.cos(t)];
    const c = [0.7, -0.3, 2];
    const r = Math.hypot(c[0], c[1], c[2]);
    const cosL = Math.abs(c[0] * n[0] + c[1] * n[1] + c[2] * n[2]) / r;
    let prev = Infinity;
    for (const s of [0.4, 0.1, 0.025, 0.00625]) {
      const corner = [0, 1, 2].map((k) => c[k] - (s / 2) * ex[k] - (s / 2) * ey[k]);
      const exact = parallelogramSolidAngle(
        corner[0],
        corner[1],
        corner[2],
        s * ex[0],
        s * ex[1],
        s * ex[2],
        s * ey[0],
        s * ey[1],
        s * ey[2],
      );
      const approx = patchSolidAngleApprox(s * s, cosL, r);
      const rel = Math.abs(approx - exact) / exact;
      expect(rel).toBeLessThan(prev / 10); // quartering the size cuts the error ≥ 10× (≈ 16×)
      prev = rel;
    }
    expect(prev).toBeLessThan(1e-5);
  });
  it('returns 0 rather than Infinity or NaN at r = 0 or with non-finite input', () => {
    expect(patchSolidAngleApprox(1, 1, 0)).toBe(0);
    expect(patchSolidAngleApprox(NaN, 1, 1)).toBe(0);
    expect(patchSolidAngleApprox(1, Infinity, 1)).toBe(0);
  });
});

describe('aligned-rectangle closed form', () => {
  it('agrees with Van Oosterom–Strackee for near, off-axis rectangles', async () => {
    const { alignedRectangleSolidAngle } = await import('../../../src/core/geometry/solidAngle');
    for (const [x0, x1, y0, y1, d] of [
      [-0.5, 0.5, -0.5, 0.5, 2],
      [0.3, 2, -1, 0.1, 0.4],
      [1, 3, 1, 2, -1],
    ] as const) {
      const ref = rectOmegaBig(x0, x1, y0, y1, d);
      expect(Math.abs(alignedRectangleSolidAngle(x0, x1, y0, y1, d) - ref)).toBeLessThan(1e-14);
    }
    expect(alignedRectangleSolidAngle(0, 1, 0, 1, 0)).toBe(0);
  });
});
