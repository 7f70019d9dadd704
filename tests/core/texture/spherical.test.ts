import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { spherePoint, sphericalUV } from '../../../src/core/texture';

describe('sphericalUV', () => {
  it('the exam point (y/x = 1, z/r = √2/2) is (π/4, π/4), normalized (1/8, 1/4), at any radius', () => {
    for (const r of [1e-300, 1, 2, 1e300]) {
      const p = sphericalUV(r / 2, r / 2, r * Math.SQRT1_2);
      expect(p.ok).toBe(true);
      if (!p.ok) continue;
      expect(p.r / r).toBeCloseTo(1, 14);
      expect(p.phi).toBeCloseTo(Math.PI / 4, 15);
      expect(p.theta).toBeCloseTo(Math.PI / 4, 15);
      expect(p.u).toBeCloseTo(0.125, 15);
      expect(p.v).toBeCloseTo(0.25, 15);
    }
  });

  it('covers the four quadrants with u in [0, 1) (atan2 < 0 gets + 2π)', () => {
    const cases: [number, number, number][] = [
      [1, 0, 0],
      [0, 1, 0.25],
      [-1, 0, 0.5],
      [0, -1, 0.75],
      [1, -1, 0.875],
      [-1, -1, 0.625],
    ];
    for (const [x, y, u] of cases) {
      const p = sphericalUV(x, y, 0);
      if (!p.ok) throw new Error(p.message);
      expect(p.u).toBeCloseTo(u, 15);
      expect(p.v).toBeCloseTo(0.5, 15);
    }
    // −0 in y: still the seam's u = 0 side, never u = 1
    const s = sphericalUV(1, -0, 0);
    expect(s.ok && s.u).toBe(0);
  });

  it('never returns u = 1 at the seam, even when atan2 + 2π rounds to 2π', () => {
    expect(Math.atan2(-1e-300, 1) + 2 * Math.PI).toBe(2 * Math.PI); // the rounding in question
    const p = sphericalUV(1, -1e-300, 0);
    expect(p.ok).toBe(true);
    if (p.ok) {
      expect(p.u).toBe(0);
      expect(p.phi).toBe(0);
    }
    const q = sphericalUV(1, -1e-15, 0);
    if (q.ok) expect(q.u).toBeLessThan(1);
  });

  it('defines u = 0 at the poles and gives v = 0 (north) and v = 1 (south), whatever the zero signs', () => {
    for (const [x, y] of [
      [0, 0],
      [-0, 0],
      [0, -0],
      [-0, -0],
    ]) {
      const n = sphericalUV(x, y, 3);
      const s = sphericalUV(x, y, -3);
      if (!n.ok || !s.ok) throw new Error('pole rejected');
      expect([n.u, n.v, n.pole]).toEqual([0, 0, true]);
      expect([s.u, s.v, s.pole]).toEqual([0, 1, true]);
    }
  });

  it('keeps full precision near the poles (where arccos(z/r) would lose the angle)', () => {
    const e = 1e-10;
    const p = sphericalUV(e, 0, 1);
    if (!p.ok) throw new Error(p.message);
    expect(p.theta / e).toBeCloseTo(1, 12); // θ ≈ atan(e) = e − e³/3
    // the naive arccos(z/r) rounds z/r to 1 and returns 0 here
    expect(Math.acos(1 / Math.hypot(e, 0, 1))).toBe(0);
    expect(p.pole).toBe(false);
  });

  it('rejects the origin and non-finite points with a clear message', () => {
    const o = sphericalUV(0, 0, 0);
    expect(o.ok).toBe(false);
    if (!o.ok) expect(o.message).toMatch(/centre/);
    const n = sphericalUV(NaN, 1, 1);
    expect(n.ok).toBe(false);
    if (!n.ok) expect(n.message).toMatch(/finite/);
    expect(sphericalUV(Infinity, 0, 0).ok).toBe(false);
  });

  it('round-trips spherePoint (property over the whole (u, v) square)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 1, noNaN: true, maxExcluded: true }),
        fc.double({ min: 1e-6, max: 1 - 1e-6, noNaN: true }),
        fc.double({ min: 1e-100, max: 1e100, noNaN: true }),
        (u, v, r) => {
          const [x, y, z] = spherePoint(u, v, r);
          const p = sphericalUV(x, y, z);
          if (!p.ok) return false;
          if (!(p.u >= 0 && p.u < 1 && p.v >= 0 && p.v <= 1)) return false;
          const du = Math.min(Math.abs(p.u - u), 1 - Math.abs(p.u - u)); // distance on the circle
          return du < 1e-12 && Math.abs(p.v - v) < 1e-12 && Math.abs(p.r / r - 1) < 1e-12;
        },
      ),
    );
  });

  it('returns in-range, finite values for arbitrary non-zero points (property)', () => {
    fc.assert(
      fc.property(
        fc.double({ noNaN: true, noDefaultInfinity: true }),
        fc.double({ noNaN: true, noDefaultInfinity: true }),
        fc.double({ noNaN: true, noDefaultInfinity: true }),
        (x, y, z) => {
          const p = sphericalUV(x, y, z);
          if (x === 0 && y === 0 && z === 0) return !p.ok;
          if (!p.ok) return false;
          return (
            p.u >= 0 &&
            p.u < 1 &&
            p.v >= 0 &&
            p.v <= 1 &&
            p.phi >= 0 &&
            p.phi < 2 * Math.PI &&
            p.theta >= 0 &&
            p.theta <= Math.PI
          );
        },
      ),
    );
  });
});
