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
import { chi2Test } from '../../../src/core/verify';
import { rectAreaPdf, sampleRectArea } from '../../../src/core/lights/areaSampling';
import { rectProjectedSolidAngle } from '../../../src/core/lights/polygonIrradiance';

const STRESS = [0, 2 ** -53, 0.5, 1 - 2 ** -53];

/** Local coordinates of a point relative to the light's corner: (a along ex, b along ey, c off-plane). */
function local(l: RectLight, x: readonly number[]): [number, number, number] {
  const d = [x[0] - l.corner[0], x[1] - l.corner[1], x[2] - l.corner[2]];
  const dot = (v: readonly number[]) => d[0] * v[0] + d[1] * v[1] + d[2] * v[2];
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
      expect(sphericalRectanglePdf(q, ...l.center)).toBeCloseTo(1 / q.solidAngle, 9);
      // 0 outside the support: off the plane, beyond an edge; never NaN.
      const off = [l.center[0] + l.normal[0], l.center[1] + l.normal[1], l.center[2] + l.normal[2]] as const;
      expect(sphericalRectanglePdf(q, ...off)).toBe(0);
      const beyond = [0, 1, 2].map((k) => l.corner[k] + 1.01 * l.edgeX[k] + 0.5 * l.edgeY[k]) as [
        number,
        number,
        number,
      ];
      expect(sphericalRectanglePdf(q, ...beyond)).toBe(0);
      expect(sphericalRectanglePdf(q, NaN, 0, 0)).toBe(0);
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
          const [v1, v2] = invertSphericalRectangleSample(q, out[0], out[1], out[2]);
          expect(Math.abs(v1 - u1)).toBeLessThan(1e-7);
          expect(Math.abs(v2 - u2)).toBeLessThan(1e-7);
        }
    });
    it(`${name}: round trip invert(sample(u)) ≈ u over the square (fast-check)`, () => {
      const out = [0, 0, 0];
      fc.assert(
        fc.property(
          fc.double({ min: 0, max: 1, noNaN: true }),
          fc.double({ min: 0, max: 1, noNaN: true }),
          (u1, u2) => {
            sampleSphericalRectangle(q, u1, u2, out);
            const [v1, v2] = invertSphericalRectangleSample(q, out[0], out[1], out[2]);
            expect(Math.abs(v1 - u1)).toBeLessThan(1e-7);
            expect(Math.abs(v2 - u2)).toBeLessThan(1e-7);
          },
        ),
        { seed: 11, numRuns: 200 },
      );
    });
    it(`${name}: the map is area-preserving — a grid cell du₁du₂ maps to solid angle Ω du₁du₂`, () => {
      // Image of each cell of a 6×6 grid: the spherical quadrilateral of its four corner
      // directions, measured by two Van Oosterom–Strackee triangles. (Cells are small, so the
      // straight-edged quad matches the curved image to O(cell²).)
      const K = 6,
        S = 24,
        G = K * S;
      const dirs: number[][] = [];
      const out = [0, 0, 0];
      for (let i = 0; i <= G; i++)
        for (let j = 0; j <= G; j++) {
          sampleSphericalRectangle(q, i / G, j / G, out);
          dirs.push([out[0] - p[0], out[1] - p[1], out[2] - p[2]]);
        }
      const at = (i: number, j: number) => dirs[i * (G + 1) + j];
      let total = 0;
      for (let ci = 0; ci < K; ci++)
        for (let cj = 0; cj < K; cj++) {
          let cell = 0;
          for (let i = ci * S; i < (ci + 1) * S; i++)
            for (let j = cj * S; j < (cj + 1) * S; j++)
              cell +=
                triangleSolidAngle(at(i, j), at(i + 1, j), at(i + 1, j + 1)) +
                triangleSolidAngle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
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
      counts[(a < l.width / 2 ? 0 : 1) + (b < l.height / 2 ? 0 : 2)]++;
    }
    for (let k = 0; k < 4; k++) {
      const sub = makeRectLight(
        [0, 1, 2].map(
          (c) => l.corner[c] + (k & 1 ? 0.75 : 0.25) * l.edgeX[c] + (k & 2 ? 0.75 : 0.25) * l.edgeY[c],
        ),
        l.width / 2,
        l.height / 2,
        l.tiltDeg,
      );
      const pk = rectSolidAngle(sub, ...p) / q.solidAngle;
      const sigma = Math.sqrt(N * pk * (1 - pk));
      expect(Math.abs(counts[k] - N * pk)).toBeLessThan(4 * sigma);
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
    const pdf = sphericalRectanglePdf(q, out[0], out[1], out[2]);
    expect(Math.abs(pdf * q.solidAngle - 1)).toBeLessThan(1e-7); // r²/(A cos θ_l) ≈ 1/Ω for a tiny light
    expect(invertSphericalRectangleSample(q, out[0], out[1], out[2])).toEqual([0.25, 0.75]);
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
        expect(Math.abs(out[0])).toBeLessThanOrEqual(0.5 + 1e-9);
        expect(Math.abs(out[1])).toBeLessThanOrEqual(0.5 + 1e-9);
        const [v1, v2] = invertSphericalRectangleSample(q, out[0], out[1], out[2]);
        expect(Math.abs(v1 - u1)).toBeLessThan(1e-6);
        expect(Math.abs(v2 - u2)).toBeLessThan(1e-6);
      }
  });
});

describe('χ² goodness of fit on the light (8 × 8 cells, α = 0.01, Šidák over 6 tests)', () => {
  const K = 8;
  const N = 60000;
  const cases: Array<[string, RectLight, [number, number, number]]> = [
    ['near, tilted', makeRectLight([0.3, 0.4, 0.5], 2, 1.5, 35), [0, 0, 0]],
    ['overhead', makeRectLight([0, 0, 1], 1, 1, 0), [0.2, 0, 0]],
    ['grazing', makeRectLight([0, 3, 0.6], 2, 1, -80), [0, 0, 0]],
  ];
  /** Expected counts: N × Ω(cell)/Ω, each cell's Ω by Van Oosterom–Strackee. */
  function expectedCounts(l: RectLight, p: [number, number, number], total: number): Float64Array {
    const e = new Float64Array(K * K);
    const q = makeSphericalRect(l, ...p);
    for (let i = 0; i < K; i++)
      for (let j = 0; j < K; j++) {
        const cell = makeRectLight(
          [0, 1, 2].map((k) => l.corner[k] + ((i + 0.5) / K) * l.edgeX[k] + ((j + 0.5) / K) * l.edgeY[k]),
          l.width / K,
          l.height / K,
          l.tiltDeg,
        );
        e[i * K + j] = (total * rectSolidAngle(cell, ...p)) / q.solidAngle;
      }
    return e;
  }
  function histogram(
    l: RectLight,
    sample: (u1: number, u2: number, out: number[]) => void,
    seed: number,
  ): Float64Array {
    const h = new Float64Array(K * K);
    const rng = new Rng(seed);
    const out = [0, 0, 0];
    for (let n = 0; n < N; n++) {
      sample(rng.nextFloat(), rng.nextFloat(), out);
      const [a, b] = local(l, out);
      const i = Math.min(K - 1, Math.max(0, Math.floor((a / l.width) * K)));
      const j = Math.min(K - 1, Math.max(0, Math.floor((b / l.height) * K)));
      h[i * K + j]++;
    }
    return h;
  }
  for (const [name, l, p] of cases) {
    it(`${name}: the spherical-rectangle sampler passes`, () => {
      const q = makeSphericalRect(l, ...p);
      const r = chi2Test(
        histogram(l, (a, b, o) => sampleSphericalRectangle(q, a, b, o), 21),
        expectedCounts(l, p, N),
        { alpha: 0.01, tests: 6 },
      );
      expect(r.pass, `p = ${r.pValue}`).toBe(true);
    });
    it(`${name}: a deliberately broken sampler (uniform by area, or a missing square root) is rejected`, () => {
      const q = makeSphericalRect(l, ...p);
      const byArea = chi2Test(
        histogram(l, (a, b, o) => sampleRectArea(l, a, b, o), 22),
        expectedCounts(l, p, N),
        { alpha: 0.01, tests: 6 },
      );
      expect(byArea.pass).toBe(false);
      // Broken y map: h interpolated in h² instead of h (a "missing square root").
      const broken = (a: number, b: number, o: number[]) => sampleSphericalRectangle(q, a, b * b, o);
      const r = chi2Test(histogram(l, broken, 23), expectedCounts(l, p, N), { alpha: 0.01, tests: 6 });
      expect(r.pass).toBe(false);
    });
  }
  it('uniform area sampling passes against area-proportional expected counts; pdf 1/|A| on, 0 off', () => {
    const l = makeRectLight([0.3, 0.4, 0.5], 2, 1.5, 35);
    const e = new Float64Array(K * K).fill(N / (K * K));
    const r = chi2Test(
      histogram(l, (a, b, o) => sampleRectArea(l, a, b, o), 24),
      e,
      { alpha: 0.01 },
    );
    expect(r.pass).toBe(true);
    expect(rectAreaPdf(l, ...l.center)).toBeCloseTo(1 / 3, 15);
    expect(rectAreaPdf(l, l.center[0] + 5, l.center[1], l.center[2])).toBe(0);
    expect(rectAreaPdf(makeRectLight([0, 0, 1], 0, 1), 0, 0, 1)).toBe(0);
  });
});

describe('properties over whole input ranges (fast-check)', () => {
  const vec = (lo: number, hi: number) =>
    fc.tuple(
      fc.double({ min: lo, max: hi, noNaN: true }),
      fc.double({ min: lo, max: hi, noNaN: true }),
      fc.double({ min: lo, max: hi, noNaN: true }),
    );
  it('any light, any point off its plane: samples lie on the light, pdf = 1/Ω there, inverse recovers u', () => {
    fc.assert(
      fc.property(
        vec(-5, 5),
        fc.double({ min: 0.01, max: 5, noNaN: true }),
        fc.double({ min: 0.01, max: 5, noNaN: true }),
        fc.double({ min: -180, max: 180, noNaN: true }),
        vec(-5, 5),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (c, w, h, t, p, u1, u2) => {
          const l = makeRectLight(c, w, h, t);
          const q = makeSphericalRect(l, ...p);
          // Away from the degenerate limit p → the light's plane (|z₀| → 0), where Ω → 2π and the map
          // squeezes the whole light into grazing directions (round trips then need more than 53 bits).
          fc.pre(q.solidAngle > 1e-4 && Math.abs(q.z0) > 1e-2 * Math.max(w, h));
          const out = [0, 0, 0];
          sampleSphericalRectangle(q, u1, u2, out);
          expect(out.every(Number.isFinite)).toBe(true);
          const pdf = sphericalRectanglePdf(q, out[0], out[1], out[2]);
          expect(pdf).toBeCloseTo(1 / q.solidAngle, 6);
          expect(q.solidAngle).toBeLessThanOrEqual(2 * Math.PI);
          const [v1, v2] = invertSphericalRectangleSample(q, out[0], out[1], out[2]);
          expect(Math.abs(v1 - u1)).toBeLessThan(1e-5);
          expect(Math.abs(v2 - u2)).toBeLessThan(1e-5);
        },
      ),
      { seed: 2024, numRuns: 400 },
    );
  });
  it('any point, even 1e-12 from the plane: finite samples on the light with positive pdf; ∫cos θ dω ≤ min(Ω, π)', () => {
    fc.assert(
      fc.property(
        vec(-5, 5),
        fc.double({ min: 0.01, max: 5, noNaN: true }),
        fc.double({ min: 0.01, max: 5, noNaN: true }),
        fc.double({ min: -180, max: 180, noNaN: true }),
        vec(-5, 5),
        fc.double({ min: -12, max: 0, noNaN: true }),
        fc.constantFrom(0, 2 ** -53, 0.5, 1 - 2 ** -53),
        fc.constantFrom(0, 2 ** -53, 0.5, 1 - 2 ** -53),
        (c, w, h, t, p0, logd, u1, u2) => {
          const l = makeRectLight(c, w, h, t);
          // Move p to distance 10^logd from the plane, in front of the light.
          const dist =
            (p0[0] - l.center[0]) * l.normal[0] +
            (p0[1] - l.center[1]) * l.normal[1] +
            (p0[2] - l.center[2]) * l.normal[2];
          const p = [0, 1, 2].map((k) => p0[k] + (10 ** logd - dist) * l.normal[k]) as [
            number,
            number,
            number,
          ];
          const q = makeSphericalRect(l, ...p);
          fc.pre(q.solidAngle > 0);
          const out = [0, 0, 0];
          sampleSphericalRectangle(q, u1, u2, out);
          const [a, b, cc] = local(l, out);
          expect(out.every(Number.isFinite)).toBe(true);
          expect(a).toBeGreaterThanOrEqual(-1e-9 * w);
          expect(a).toBeLessThanOrEqual(w * (1 + 1e-9));
          expect(b).toBeGreaterThanOrEqual(-1e-9 * h);
          expect(b).toBeLessThanOrEqual(h * (1 + 1e-9));
          expect(Math.abs(cc)).toBeLessThan(1e-8);
          expect(sphericalRectanglePdf(q, out[0], out[1], out[2])).toBeGreaterThan(0);
          const proj = rectProjectedSolidAngle(l, ...p);
          expect(proj).toBeGreaterThanOrEqual(0);
          expect(proj).toBeLessThanOrEqual(Math.min(q.solidAngle, Math.PI) * (1 + 1e-12) + 1e-15);
        },
      ),
      { seed: 77, numRuns: 400 },
    );
  });
});
