import { describe, expect, it } from 'vitest';
import {
  intersectRect,
  makeRectLight,
  rectFacesPoint,
  rectPlaneDistance,
  rectSolidAngle,
  sinCosDeg,
} from '../../../src/core/lights/rectLight';
import { centredRectangleSolidAngle } from '../../../src/core/geometry/solidAngle';

describe('rectangle light frame', () => {
  it('tilt 0 faces −z with corners counter-clockwise about ex × ey', () => {
    const l = makeRectLight([0, 0, 2], 1, 0.5, 0);
    expect(l.normal).toEqual([0, 0, -1]);
    expect(l.area).toBe(0.5);
    expect(l.corners[0]).toEqual([-0.5, -0.25, 2]);
    expect(l.corners[2]).toEqual([0.5, 0.25, 2]);
  });
  it('tilt 90 faces +y, tilt 180 faces exactly +z (multiples of 90° are exact)', () => {
    expect(makeRectLight([0, 0, 2], 1, 1, 90).normal).toEqual([0, 1, 0]);
    const back = makeRectLight([0, 0, 2], 1, 1, 180);
    expect(back.normal[2]).toBe(1);
    expect(back.normal[1]).toBe(0);
    expect(sinCosDeg(-90)).toEqual([-1, 0]);
    expect(sinCosDeg(450)).toEqual([1, 0]);
  });
  it('the frame is orthonormal and the normal is ey × ex for any tilt', () => {
    for (const t of [13, 45, 120, -33.3]) {
      const l = makeRectLight([1, 2, 3], 2, 3, t);
      const { ex, ey, normal: n } = l;
      const dot = (a: readonly number[], b: readonly number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      expect(dot(ex, ey)).toBeCloseTo(0, 15);
      expect(dot(ey, n)).toBeCloseTo(0, 15);
      expect(dot(n, n)).toBeCloseTo(1, 15);
      const cross = [
        ey[1] * ex[2] - ey[2] * ex[1],
        ey[2] * ex[0] - ey[0] * ex[2],
        ey[0] * ex[1] - ey[1] * ex[0],
      ];
      expect(cross[1]).toBeCloseTo(n[1], 15);
      expect(cross[2]).toBeCloseTo(n[2], 15);
    }
  });
  it('bad sizes give a degenerate light of area 0', () => {
    expect(makeRectLight([0, 0, 1], -1, 1).area).toBe(0);
    expect(makeRectLight([0, 0, 1], NaN, 1).area).toBe(0);
    expect(makeRectLight([0, 0, 1], 1, Infinity).area).toBe(0);
  });
  it('faces the floor point below it, not the point above it or on its plane', () => {
    const l = makeRectLight([0, 0, 2], 1, 1, 0);
    expect(rectFacesPoint(l, 0, 0, 0)).toBe(true);
    expect(rectFacesPoint(l, 0, 0, 3)).toBe(false);
    expect(rectFacesPoint(l, 0, 0, 2)).toBe(false);
    expect(rectPlaneDistance(l, 0, 0, 0)).toBe(2);
  });
  it('solid angle from the axis equals the centred closed form', () => {
    const l = makeRectLight([0.3, -0.2, 2.5], 1.2, 0.7, 0);
    expect(rectSolidAngle(l, 0.3, -0.2, 0)).toBeCloseTo(centredRectangleSolidAngle(1.2, 0.7, 2.5), 14);
    expect(rectSolidAngle(makeRectLight([0, 0, 2], 0, 1), 0, 0, 0)).toBe(0);
  });
});

describe('ray–rectangle intersection', () => {
  const l = makeRectLight([0, 0, 2], 1, 1, 0);
  it('hits straight up at t = 2 and at t = 1 for d of length 2', () => {
    expect(intersectRect(l, 0, 0, 0, 0, 0, 1)).toBe(2);
    expect(intersectRect(l, 0, 0, 0, 0, 0, 2)).toBe(1);
  });
  it('misses: outside the edges, parallel, behind the origin, degenerate', () => {
    expect(intersectRect(l, 0, 0, 0, 0.3, 0, 1)).toBe(Infinity); // hits the plane at x = 0.6 > 0.5
    expect(intersectRect(l, 0, 0, 0, 1, 0, 0)).toBe(Infinity);
    expect(intersectRect(l, 0, 0, 0, 0, 0, -1)).toBe(Infinity);
    expect(intersectRect(makeRectLight([0, 0, 2], 0, 0), 0, 0, 0, 0, 0, 1)).toBe(Infinity);
  });
  it('edges are inclusive; a ray from the back side hits too (the rectangle is two-sided geometry)', () => {
    expect(intersectRect(l, 0, 0, 0, 0.25, 0, 1)).toBe(2);
    expect(intersectRect(l, 0, 0, 4, 0, 0, -1)).toBe(2);
  });
});
