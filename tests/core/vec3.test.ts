import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { add, addScaled, cross, distance, dot, norm, normalize, sameVec, sub } from '../../src/core/vec3';

const finite = fc.double({ min: -1e6, max: 1e6, noNaN: true });
const v3 = fc.tuple(finite, finite, finite);

describe('vec3', () => {
  it('cross is orthogonal to both factors and anti-commutes', () => {
    fc.assert(
      fc.property(v3, v3, (a, b) => {
        const c = cross(a, b);
        const scaleAB = norm(a) * norm(b);
        expect(Math.abs(dot(c, a))).toBeLessThanOrEqual(1e-12 * scaleAB * norm(a) + 1e-300);
        expect(Math.abs(dot(c, b))).toBeLessThanOrEqual(1e-12 * scaleAB * norm(b) + 1e-300);
        const ba = cross(b, a);
        for (let i = 0; i < 3; i++) expect(ba[i] + c[i]).toBe(0);
      }),
      { seed: 7 },
    );
  });
  it('the right-handed basis: x × y = z', () => {
    expect(cross([1, 0, 0], [0, 1, 0])).toEqual([0, 0, 1]);
    expect(cross([0, 1, 0], [0, 0, 1])).toEqual([1, 0, 0]);
  });
  it('add, sub, addScaled and distance agree', () => {
    fc.assert(
      fc.property(v3, v3, finite, (a, b, s) => {
        expect(
          sub(add(a, b), b).every(
            (x, i) => Math.abs(x - a[i]) <= 1e-9 * (Math.abs(a[i]) + Math.abs(b[i]) + 1),
          ),
        ).toBe(true);
        const p = addScaled(a, b, s);
        expect(p[0]).toBe(a[0] + s * b[0]);
        expect(distance(a, b)).toBe(norm(sub(a, b)));
      }),
      { seed: 11 },
    );
  });
  it('norm does not overflow or underflow and normalize gives unit length', () => {
    expect(norm([3e200, 4e200, 0])).toBeCloseTo(5e200, -190);
    expect(norm([3e-200, 4e-200, 0])).toBeGreaterThan(0);
    expect(norm(normalize([1e-300, 2e-300, 2e-300]))).toBeCloseTo(1, 14);
    expect(normalize([0, 0, 0])).toEqual([0, 0, 0]);
  });
  it('sameVec tells −0 from 0 and matches NaN with NaN', () => {
    expect(sameVec([0, 1, 2], [-0, 1, 2])).toBe(false);
    expect(sameVec([NaN, 1, 2], [NaN, 1, 2])).toBe(true);
    expect(sameVec([1, 2], [1, 2, 3])).toBe(false);
  });
});
