import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { makeRectLight, rectSolidAngle, type RectLight } from '../../../src/core/lights/rectLight';
import {
  invertSphericalRectangleSample,
  makeSphericalRect,
  sampleSphericalRectangle,
  sphericalRectanglePdf,
  SPHERICAL_RECT_MIN_SOLID_ANGLE,
} from '../../../src/core/lights/sphericalRectangle';
import { triangleSolidAngle } from '../../../src/core/geometry/solidAngle';
import { Rng } from '../../../src/core/random';

const STRESS = [0, 2 ** -53, 0.5, 1 - 2 ** -53];

/** Local coordinates of a point relative to the light's corner: (a along ex, b along ey, c off-plane). */
function local(l: RectLight, x: number[]): [number, number, number] {
  const d = [x[0]! - l.corner[0], x[1]! - l.corner[1], x[2]! - l.corner[2]];
  const dot = (v: number[]) => d[0]! * v[0]! + d[1]! * v[1]! + d[2]! * v[2]!;
  return [dot(l.ex), dot(l.ey), dot(l.normal)];
}

const placements: Array<[string, RectLight, [number, number, number]]> = [
  ['overhead', makeRectLight([0, 0, 2], 1, 1, 0), [0, 0, 0]],
  ['off to the side, tilted', makeRectLight([1.5, 0.4, 1], 2, 0.5, 60), [0, 0, 0]],
  ['seen from behind', makeRectLight([0, 0, 2], 1, 1, 180), [0.2, 0.1, 0]],
  ['very near', makeRectLight([0, 0, 0.01], 1, 1, 0), [0.1, -0.2, 0]],
  ['far', makeRectLight([0, 0, 200], 1, 1, 0), [0, 0, 0]],
];

describe('spherical rectangle sampling (Ureña et al. 2013)', () => {
  for (const [name, l, p] of placements) {
    const q = makeSphericalRect(l, ...p);
    it(`${name}: Ω equals the rectangle's solid angle and pdf = 1/Ω`, () => {
      expect(q.solidAngle).toBeGreaterThan(0);
      expect(q.solidAngle).toBeCloseTo(rectSolidAngle(l, ...p), 14);
      // The interior-angle form Σγ − 2π agrees where it is accurate.
      expect(q.g0 + q.g1 + q.g2 + q.g3 - 2 * Math.PI).toBeCloseTo(q.solidAngle, 9);
      expect(sphericalRectanglePdf(q)).toBeCloseTo(1 / q.solidAngle, 9);
    });
    it(`${name}: samples lie on the rectangle for stress ξ and the inverse recovers ξ`, () => {
      const out = [0, 0, 0];
      for (const u1 of STRESS)
        for (const u2 of STRESS) {
          sampleSphericalRectangle(q, u1, u2, out);
          const [a, b, c] = local(l, out);
          expect(a).toBeGreaterThanOrEqual(-1e-9 * l.width);
          expect(a).toBeLessThanOrEqual(l.width * (1 + 1e-9));
          expect(b).toBeGreaterThanOrEqual(-1e-9 * l.height);
          expect(b).toBeLessThanOrEqual(l.height * (1 + 1e-9));
          expect(Math.abs(c)).toBeLessThan(1e-9 * (1 + Math.abs(l.center[2])));
          const [v1, v2] = invertSphericalRectangleSample(q, out[0]!, out[1]!, out[2]!);
          expect(Math.abs(v1 - u1)).toBeLessThan(1e-7);
          expect(Math.abs(v2 - u2)).toBeLessThan(1e-7);
        }
    });
    it(`${name}: round trip invert(sample(u)) ≈ u over the square (fast-check)`, () => {
      const out = [0, 0, 0];
      fc.assert(
        fc.property(fc.double({ min: 0, max: 1, noNaN: true }), fc.double({ min: 0, max: 1, noNaN: true }), (u1, u2) => {
          sampleSphericalRectangle(q, u1, u2, out);
          const [v1, v2] = invertSphericalRectangleSample(q, out[0]!, out[1]!, out[2]!);
          expect(Math.abs(v1 - u1)).toBeLessThan(1e-7);
          expect(Math.abs(v2 - u2)).toBeLessThan(1e-7);
        }),
        { seed: 11, numRuns: 200 },
      );
    });
    it(`${name}: the map is area-preserving — a grid cell du₁du₂ maps to solid angle Ω du₁du₂`, () => {
      // Image of each cell of a 6×6 grid: the spherical quadrilateral of its four corner
      // directions, measured by two Van Oosterom–Strackee triangles. (Cells are small, so the
      // straight-edged quad matches the curved image to O(cell²).)
      const K = 6, S = 24, G = K * S;
      const dirs: number[][] = [];
      const out = [0, 0, 0];
      for (let i = 0; i <= G; i++)
        for (let j = 0; j <= G; j++) {
          sampleSphericalRectangle(q, i / G, j / G, out);
          dirs.push([out[0]! - p[0], out[1]! - p[1], out[2]! - p[2]]);
        }
      const at = (i: number, j: number) => dirs[i * (G + 1) + j]!;
      let total = 0;
      for (let ci = 0; ci < K; ci++)
        for (let cj = 0; cj < K; cj++) {
          let cell = 0;
          for (let i = ci * S; i < (ci + 1) * S; i++)
            for (let j = cj * S; j < (cj + 1) * S; j++)
              cell += triangleSolidAngle(at(i, j), at(i + 1, j), at(i + 1, j + 1)) + triangleSolidAngle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
          total += cell;
          expect(cell / (q.solidAngle / (K * K))).toBeGreaterThan(0.99);
          expect(cell / (q.solidAngle / (K * K))).toBeLessThan(1.01);
        }
      expect(total / q.solidAngle).toBeCloseTo(1, 3);
    });
  }

  it('samples fall in sub-rectangles with frequency Ω_sub/Ω (binomial, 4σ)', () => {
    const l = makeRectLight([0.8, 0.2, 1.2], 2, 1.5, 30);
    const p: [number, number, number] = [0, 0, 0];
    const q = makeSphericalRect(l, ...p);
    const N = 40000;
    const rng = new Rng(7);
    const out = [0, 0, 0];
    const counts = [0, 0, 0, 0];
    for (let i = 0; i < N; i++) {
      sampleSphericalRectangle(q, rng.nextFloat(), rng.nextFloat(), out);
      const [a, b] = local(l, out);
      counts[(a < l.width / 2 ? 0 : 1) + (b < l.height / 2 ? 0 : 2)]!++;
    }
    for (let k = 0; k < 4; k++) {
      const sub = makeRectLight(
        [0, 1, 2].map((c) => l.corner[c]! + ((k & 1 ? 0.75 : 0.25) * l.edgeX[c]!) + ((k & 2 ? 0.75 : 0.25) * l.edgeY[c]!)),
        l.width / 2, l.height / 2, l.tiltDeg,
      );
      const pk = rectSolidAngle(sub, ...p) / q.solidAngle;
      const sigma = Math.sqrt(N * pk * (1 - pk));
      expect(Math.abs(counts[k]! - N * pk)).toBeLessThan(4 * sigma);
    }
  });

  it('tiny, distant lights fall back to area sampling with a consistent pdf; Ω = 0 gives pdf 0', () => {
    const l = makeRectLight([0, 0, 1e4], 1, 1, 0);
    const q = makeSphericalRect(l, 0, 0, 0);
    expect(q.solidAngle).toBeLessThan(SPHERICAL_RECT_MIN_SOLID_ANGLE);
    expect(q.areaFallback).toBe(true);
    const out = [0, 0, 0];
    sampleSphericalRectangle(q, 0.25, 0.75, out);
    expect(out[0]).toBeCloseTo(-0.25, 12);
    expect(out[1]).toBeCloseTo(0.25, 12);
    const pdf = sphericalRectanglePdf(q, out[0]!, out[1]!, out[2]!);
    expect(Math.abs(pdf * q.solidAngle - 1)).toBeLessThan(1e-7); // r²/(A cos θ_l) ≈ 1/Ω for a tiny light
    expect(invertSphericalRectangleSample(q, out[0]!, out[1]!, out[2]!)).toEqual([0.25, 0.75]);
    const flat = makeSphericalRect(makeRectLight([0, 0, 0], 1, 1, 0), 0.2, 0.2, 0);
    expect(flat.solidAngle).toBe(0);
    expect(sphericalRectanglePdf(flat, 0.2, 0.2, 0)).toBe(0);
  });

  it('just above the fallback threshold the sampler still stays on the light and inverts', () => {
    const l = makeRectLight([0, 0, 800], 1, 1, 0); // Ω ≈ 1.56e-6
    const q = makeSphericalRect(l, 0, 0, 0);
    expect(q.areaFallback).toBe(false);
    const out = [0, 0, 0];
    for (const u1 of STRESS)
      for (const u2 of STRESS) {
        sampleSphericalRectangle(q, u1, u2, out);
        expect(Math.abs(out[0]!)).toBeLessThanOrEqual(0.5 + 1e-9);
        expect(Math.abs(out[1]!)).toBeLessThanOrEqual(0.5 + 1e-9);
        const [v1, v2] = invertSphericalRectangleSample(q, out[0]!, out[1]!, out[2]!);
        expect(Math.abs(v1 - u1)).toBeLessThan(1e-6);
        expect(Math.abs(v2 - u2)).toBeLessThan(1e-6);
      }
  });
});
