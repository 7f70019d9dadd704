import { describe, expect, it } from 'vitest';
import { all, create } from 'mathjs';
import { makeRectLight, type RectLight } from '../../../src/core/lights/rectLight';
import {
  clipPolygonToHalfSpace,
  lambertianFloorRadiance,
  polygonProjectedSolidAngle,
  rectProjectedSolidAngle,
} from '../../../src/core/lights/polygonIrradiance';

const M = create(all, { number: 'BigNumber', precision: 50 });

/**
 * Closed form: point to a parallel rectangle a × b at height c with one corner straight above
 * (configuration factor, Howell's catalogue B-3 / Modest, "Radiative Heat Transfer", App. D):
 * F = 1/(2π) [X/√(1+X²) atan(Y/√(1+X²)) + Y/√(1+Y²) atan(X/√(1+Y²))], X = a/c, Y = b/c.
 * The projected solid angle is π F. Evaluated in BigNumber.
 */
function cornerProjectedBig(a: number, b: number, c: number): number {
  const X = M.bignumber(a).div(c);
  const Y = M.bignumber(b).div(c);
  const sx = X.times(X).plus(1).sqrt();
  const sy = Y.times(Y).plus(1).sqrt();
  const t = X.div(sx)
    .times(Y.div(sx).atan())
    .plus(Y.div(sy).times(X.div(sy).atan()));
  return t.div(2).toNumber();
}

/** Midpoint-rule quadrature of ∫_A max(0, cos θ) cos θ_l / r² dA (the area form, Q6(b)). */
function quadrature(l: RectLight, p: [number, number, number], K = 1500): number {
  let sum = 0;
  for (let i = 0; i < K; i++)
    for (let j = 0; j < K; j++) {
      const a = (i + 0.5) / K,
        b = (j + 0.5) / K;
      const x = [0, 1, 2].map((k) => l.corner[k] + a * l.edgeX[k] + b * l.edgeY[k] - p[k]);
      const r2 = x[0] ** 2 + x[1] ** 2 + x[2] ** 2;
      const r = Math.sqrt(r2);
      const cosT = x[2] / r;
      const cosL = -(x[0] * l.normal[0] + x[1] * l.normal[1] + x[2] * l.normal[2]) / r;
      if (cosT > 0 && cosL > 0) sum += (cosT * cosL) / r2;
    }
  return (sum * l.area) / (K * K);
}

describe("Lambert's formula for a polygon", () => {
  it('a parallel rectangle with a corner overhead matches the configuration-factor closed form', () => {
    for (const [a, b, c] of [
      [1, 1, 1],
      [2, 0.5, 3],
      [0.01, 0.02, 1],
      [50, 50, 0.1],
    ] as const) {
      const l = makeRectLight([a / 2, b / 2, c], a, b, 0);
      const ref = cornerProjectedBig(a, b, c);
      expect(Math.abs(rectProjectedSolidAngle(l, 0, 0, 0) - ref) / ref).toBeLessThan(1e-12);
    }
  });
  it('tiny, distant lights (up to 1e8 × their size): within 1e-13 of the BigNumber closed form', () => {
    for (const D of [1e2, 1e4, 1e6, 1e8]) {
      const l = makeRectLight([0.5, 0.25, D], 1, 0.5, 0);
      const ref = cornerProjectedBig(1, 0.5, D);
      const got = rectProjectedSolidAngle(l, 0, 0, 0);
      expect(ref).toBeGreaterThan(0);
      expect(Math.abs(got - ref) / ref).toBeLessThan(1e-13);
    }
  });
  it('by symmetry, a centred square is four corner rectangles', () => {
    const l = makeRectLight([0, 0, 2], 1.4, 0.6, 0);
    const ref = 4 * cornerProjectedBig(0.7, 0.3, 2);
    expect(Math.abs(rectProjectedSolidAngle(l, 0, 0, 0) - ref) / ref).toBeLessThan(1e-12);
  });
  it('an enormous close light tends to the whole hemisphere, π', () => {
    const l = makeRectLight([0, 0, 1e-3], 1e4, 1e4, 0);
    expect(rectProjectedSolidAngle(l, 0, 0, 0)).toBeCloseTo(Math.PI, 6);
    expect(rectProjectedSolidAngle(l, 0, 0, 0)).toBeLessThanOrEqual(Math.PI);
  });
  it('tilted, partly below the horizon and near lights agree with quadrature of the area form', () => {
    const cases: Array<[RectLight, [number, number, number]]> = [
      [makeRectLight([0.5, 0.3, 1.5], 1, 2, 35), [0, 0, 0]],
      [makeRectLight([0, 1, 0.2], 1, 1, -90), [0, 0, 0]], // vertical, facing −y, 30% below the horizon
      [makeRectLight([0.2, 0.8, 0.1], 2, 1, -60), [0, 0, 0]], // straddles the horizon, tilted
      [makeRectLight([0, 0, 0.3], 1, 1, 0), [0.1, 0.1, 0]],
    ];
    for (const [l, p] of cases) {
      const ref = quadrature(l, p);
      expect(ref).toBeGreaterThan(0);
      expect(Math.abs(rectProjectedSolidAngle(l, ...p) - ref) / ref).toBeLessThan(2e-4);
    }
  });
  it('is 0 when the light faces away, lies wholly below the horizon, or the point is on its plane', () => {
    expect(rectProjectedSolidAngle(makeRectLight([0, 0, 2], 1, 1, 180), 0, 0, 0)).toBe(0);
    expect(rectProjectedSolidAngle(makeRectLight([0, 3, -1], 1, 1, -90), 0, 0, 0)).toBe(0);
    expect(rectProjectedSolidAngle(makeRectLight([0, 0, 2], 1, 1, 0), 0, 0, 2)).toBe(0);
    expect(rectProjectedSolidAngle(makeRectLight([0, 0, 2], 0, 1, 0), 0, 0, 0)).toBe(0);
  });
  it('L_o = (ρ/π) L ∫cos θ dω', () => {
    const l = makeRectLight([0, 0, 2], 1, 1, 0);
    expect(lambertianFloorRadiance(l, 0, 0, 0, 3, 0.5)).toBeCloseTo(
      (0.5 / Math.PI) * 3 * rectProjectedSolidAngle(l, 0, 0, 0),
      15,
    );
  });
  it('clipping keeps the part above the plane, with new vertices exactly on it', () => {
    const v = clipPolygonToHalfSpace([-1, 1, -1, 1, 1, -1, 1, 1, 1, -1, 1, 1], 0, 0, 1);
    expect(v.length).toBe(12);
    for (let i = 0; i < v.length; i += 3) expect(v[i + 2]).toBeGreaterThanOrEqual(0);
    expect(v.filter((_, i) => i % 3 === 2 && v[i] === 0).length).toBe(2);
    expect(clipPolygonToHalfSpace([0, 0, -1, 1, 0, -1, 0, 1, -1], 0, 0, 1)).toEqual([]);
    expect(polygonProjectedSolidAngle([0, 0, -1, 1, 0, -1, 0, 1, -1])).toBe(0);
  });
});
