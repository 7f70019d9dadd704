import { describe, expect, it } from 'vitest';
import { makeRectLight, type RectLight } from '../../../src/core/lights/rectLight';
import {
  lambertianFloorRadiance,
  rectProjectedSolidAngleOccluded,
} from '../../../src/core/lights/polygonIrradiance';
import {
  areaLightConvergence,
  areaLightTerms,
  estimateAreaLight,
  type AreaLightSetup,
  type LightStrategy,
} from '../../../src/core/lights/areaLightEstimators';
import { Welford } from '../../../src/core/estimators/welford';

const STRATEGIES: LightStrategy[] = ['area', 'solid-angle', 'cosine'];

function setup(
  light: RectLight,
  p: [number, number, number] = [0, 0, 0],
  occluder: RectLight | null = null,
): AreaLightSetup {
  return { light, occluder, px: p[0], py: p[1], pz: p[2], L: 2, rho: 0.8 };
}

const placements: Array<[string, AreaLightSetup]> = [
  ['overhead', setup(makeRectLight([0, 0, 2], 1, 1, 0))],
  ['tilted', setup(makeRectLight([0.8, 0.3, 1.5], 1.5, 1, 40))],
  ['partly below the horizon', setup(makeRectLight([0, 1, 0.2], 1, 1, -90))],
  ['near', setup(makeRectLight([0, 0, 0.1], 1, 1, 0), [0.2, -0.1, 0])],
  ['far', setup(makeRectLight([1, 0, 8], 1, 1, 0))],
];

describe('area-light estimators agree with the analytic reference', () => {
  for (const [name, s] of placements) {
    const ref = lambertianFloorRadiance(s.light, s.px, s.py, s.pz, s.L, s.rho);
    for (const strategy of STRATEGIES) {
      it(`${name}, ${strategy}: within 3σ of Lambert's formula`, () => {
        const n = strategy === 'cosine' ? 400000 : 100000;
        const r = estimateAreaLight(s, strategy, n, 1234, STRATEGIES.indexOf(strategy));
        expect(ref).toBeGreaterThan(0);
        expect(r.n).toBe(n);
        expect(Number.isFinite(r.stderr)).toBe(true);
        expect(Math.abs(r.estimate - ref)).toBeLessThan(3 * r.stderr + 1e-12 * ref);
      });
    }
  }

  it('solid-angle sampling of an overhead light has far less variance than cosine sampling of a far one', () => {
    const s = placements[4][1];
    const sa = estimateAreaLight(s, 'solid-angle', 20000, 5);
    const cos = estimateAreaLight(s, 'cosine', 20000, 5);
    expect(sa.stderr * 10).toBeLessThan(cos.stderr);
  });

  it('tiny, distant lights (Ω from 1e-6 down to 1e-16): area and solid-angle estimates match to 1e-6', () => {
    for (const d of [1e3, 1e5, 1e8]) {
      const s = setup(makeRectLight([0.3 * d, 0, d], 1, 1, 20));
      const ref = lambertianFloorRadiance(s.light, 0, 0, 0, s.L, s.rho);
      expect(ref).toBeGreaterThan(0);
      for (const strategy of ['area', 'solid-angle'] as const) {
        const r = estimateAreaLight(s, strategy, 2000, 8);
        // The integrand varies by O(size/d) over the light: the estimate is nearly exact, and the
        // corners themselves are only representable to ~1e-16·d, hence the 1e-7 floor at d = 1e8.
        expect(Math.abs(r.estimate - ref) / ref).toBeLessThan(d >= 1e5 ? 1e-6 : 1e-4);
        expect(Math.abs(r.estimate - ref)).toBeLessThan(3 * r.stderr + 1e-7 * ref);
      }
    }
  });

  it('facing away: reference 0 and every estimator exactly 0', () => {
    const s = setup(makeRectLight([0, 0, 2], 1, 1, 180));
    expect(lambertianFloorRadiance(s.light, 0, 0, 0, s.L, s.rho)).toBe(0);
    for (const strategy of STRATEGIES) {
      const r = estimateAreaLight(s, strategy, 5000, 9);
      expect(r.estimate).toBe(0);
      expect(r.stderr).toBe(0);
    }
  });

  it('zero-size light, L = 0, point on the light plane: all terms 0, finite', () => {
    const cases = [
      setup(makeRectLight([0, 0, 2], 0, 1, 0)),
      { ...setup(makeRectLight([0, 0, 2], 1, 1, 0)), L: 0 },
      setup(makeRectLight([0, 0, 0], 1, 1, 0)),
    ];
    for (const s of cases)
      for (const strategy of STRATEGIES) {
        const r = estimateAreaLight(s, strategy, 1000, 3);
        expect(r.estimate).toBe(0);
      }
  });

  it('stress ξ ∈ {0, 2⁻⁵³, ½, 1 − 2⁻⁵³}: finite terms and finite sample points', () => {
    const xs = [0, 2 ** -53, 0.5, 1 - 2 ** -53];
    const u = new Float64Array(32);
    let k = 0;
    for (const a of xs)
      for (const b of xs) {
        u[k++] = a;
        u[k++] = b;
      }
    for (const [, s] of placements)
      for (const strategy of STRATEGIES) {
        const terms = new Float64Array(16);
        const pts = new Float64Array(48);
        areaLightTerms(s, strategy, u, 16, terms, pts);
        for (const t of terms) expect(Number.isFinite(t) && t >= 0).toBe(true);
        for (const t of pts) expect(Number.isFinite(t)).toBe(true);
      }
  });

  it('an occluder between blocks light: estimators agree with each other and fall below the reference', () => {
    const light = makeRectLight([0, 0, 2], 1, 1, 0);
    const occ = makeRectLight([0, 0, 1], 0.4, 0.4, 0);
    const s = setup(light, [0, 0, 0], occ);
    const ref = lambertianFloorRadiance(light, 0, 0, 0, s.L, s.rho);
    const rs = STRATEGIES.map((st, i) => estimateAreaLight(s, st, 200000, 77, i));
    for (const r of rs) expect(r.estimate).toBeLessThan(ref - 5 * r.stderr);
    // The occluded analytic value (light minus the occluder's shadow, Lambert's formula).
    const occRef = (s.rho / Math.PI) * s.L * rectProjectedSolidAngleOccluded(light, occ, 0, 0, 0);
    expect(occRef).toBeLessThan(ref);
    for (const r of rs) expect(Math.abs(r.estimate - occRef)).toBeLessThan(3 * r.stderr);
    // Pairwise agreement within 3σ of the difference.
    for (let i = 0; i < 3; i++)
      for (let j = i + 1; j < 3; j++) {
        const a = rs[i],
          b = rs[j];
        expect(Math.abs(a.estimate - b.estimate)).toBeLessThan(3 * Math.hypot(a.stderr, b.stderr));
      }
  });

  it('occluded analytic value: tilted light, offset occluder, shadow partly off the light', () => {
    const light = makeRectLight([0.4, 0.6, 2], 1.5, 1, -30);
    const occ = makeRectLight([0.5, 0.2, 0.9], 0.5, 0.3, 10);
    const s = setup(light, [0, 0, 0], occ);
    const occRef = (s.rho / Math.PI) * s.L * rectProjectedSolidAngleOccluded(light, occ, 0, 0, 0);
    const ref = lambertianFloorRadiance(light, 0, 0, 0, s.L, s.rho);
    expect(occRef).toBeGreaterThan(0);
    expect(occRef).toBeLessThan(ref);
    for (const [i, st] of STRATEGIES.entries()) {
      const r = estimateAreaLight(s, st, 200000, 31, i);
      expect(Math.abs(r.estimate - occRef)).toBeLessThan(3 * r.stderr);
    }
    // An occluder beyond the light or wholly below p casts no shadow.
    expect(rectProjectedSolidAngleOccluded(light, makeRectLight([0, 0, 5], 1, 1, 0), 0, 0, 0)).toBeCloseTo(
      ref / (s.rho / Math.PI) / s.L,
      14,
    );
    expect(rectProjectedSolidAngleOccluded(light, makeRectLight([0, 0, -1], 1, 1, 0), 0, 0, 0)).toBeCloseTo(
      ref / (s.rho / Math.PI) / s.L,
      14,
    );
  });

  it('occluded analytic value when the occluder straddles p’s level or pierces the light’s plane', () => {
    const light = makeRectLight([0, 0.8, 1.2], 1.5, 1.2, -50);
    const cases = [
      makeRectLight([0.1, 0.4, 0.1], 0.6, 0.8, -90), // vertical plate standing through the floor beside p
      makeRectLight([0.2, 0.7, 1.0], 0.8, 0.8, 30), // a plate that crosses the light's plane
    ];
    for (const occ of cases) {
      const s = setup(light, [0, 0, 0], occ);
      const ps = rectProjectedSolidAngleOccluded(light, occ, 0, 0, 0);
      const occRef = (s.rho / Math.PI) * s.L * ps;
      expect(Number.isFinite(occRef)).toBe(true);
      expect(occRef).toBeLessThan(lambertianFloorRadiance(light, 0, 0, 0, s.L, s.rho));
      for (const [i, st] of STRATEGIES.entries()) {
        const r = estimateAreaLight(s, st, 200000, 57, i);
        expect(Math.abs(r.estimate - occRef), st).toBeLessThan(3 * r.stderr);
      }
    }
  });

  it('Welford accumulators merge: two halves give the same mean as the whole', () => {
    const s = placements[1][1];
    const a = estimateAreaLight(s, 'area', 3000, 42, 0).stats;
    const b = estimateAreaLight(s, 'area', 5000, 42, 1).stats;
    const m = new Welford();
    m.merge(a);
    m.merge(b);
    expect(m.count).toBe(8000);
    expect(m.mean).toBeCloseTo((a.mean * 3000 + b.mean * 5000) / 8000, 14);
  });

  it('convergence series: error shrinks roughly like N^-1/2 and the last point equals the estimate', () => {
    const s = placements[0][1];
    const ref = lambertianFloorRadiance(s.light, 0, 0, 0, s.L, s.rho);
    const cps = [100, 1000, 10000, 100000];
    const series = areaLightConvergence(s, 'area', cps, ref, 99);
    const direct = estimateAreaLight(s, 'area', 100000, 99);
    expect(series.estimate[3]).toBeCloseTo(direct.estimate, 14);
    expect(series.stderr[3] / series.stderr[0]).toBeGreaterThan(0.02);
    expect(series.stderr[3] / series.stderr[0]).toBeLessThan(0.05); // √(1/1000) ≈ 0.032
  });
});

describe('area sampling goes through the tested sample / pdf pair (core/lights/areaSampling)', () => {
  it('each area term equals f L cos θ / p_ω with p_ω = rectAreaPdf · r² / cos θ_l, computed here from sampleRectArea', async () => {
    const { sampleRectArea, rectAreaPdf } = await import('../../../src/core/lights/areaSampling');
    const s = setup(makeRectLight([0.4, -0.2, 1.7], 1.3, 0.9, 25), [0.1, 0.05, 0]);
    const u = new Float64Array([0.1, 0.9, 0.5, 0.5, 0.93, 0.02, 0.37, 0.61]);
    const terms = new Float64Array(4);
    areaLightTerms(s, 'area', u, 4, terms);
    for (let i = 0; i < 4; i++) {
      const x = [0, 0, 0];
      sampleRectArea(s.light, u[2 * i], u[2 * i + 1], x);
      const d = [x[0] - s.px, x[1] - s.py, x[2] - s.pz];
      const r2 = d[0] ** 2 + d[1] ** 2 + d[2] ** 2,
        r = Math.sqrt(r2);
      const cosT = d[2] / r;
      const cosL = -(d[0] * s.light.normal[0] + d[1] * s.light.normal[1] + d[2] * s.light.normal[2]) / r;
      const pA = rectAreaPdf(s.light, x[0], x[1], x[2]);
      expect(pA).toBeCloseTo(1 / (1.3 * 0.9), 12);
      const expected = cosT > 0 && cosL > 0 ? ((s.rho / Math.PI) * s.L * cosT * cosL) / (pA * r2) : 0;
      expect(terms[i]).toBeCloseTo(expected, 12);
    }
  });

  it('a tilted light 10⁹ away: sampled points are not rejected by the pdf’s on-rectangle test (rounding at that distance)', async () => {
    const { sampleRectArea, rectAreaPdf } = await import('../../../src/core/lights/areaSampling');
    const s = setup(makeRectLight([3e8, -2e8, 1e9], 2, 1, 30), [0, 0, 0]);
    const x = [0, 0, 0];
    for (const [a, b] of [
      [0.123, 0.877],
      [0.5, 0.25],
      [0.999, 0.001],
    ] as const) {
      sampleRectArea(s.light, a, b, x);
      expect(rectAreaPdf(s.light, x[0], x[1], x[2])).toBeCloseTo(1 / 2, 12);
    }
    const r = estimateAreaLight(s, 'area', 2000, 9, 0);
    // Small-patch limit f L |A| cos θ cos θ_l / r² at the centre: exact to O((size/r)²) ≈ 1e-18 here.
    const c = s.light.center,
      rr = Math.hypot(...c);
    const ref =
      ((s.rho / Math.PI) *
        s.L *
        s.light.area *
        (c[2] / rr) *
        (-(c[0] * s.light.normal[0] + c[1] * s.light.normal[1] + c[2] * s.light.normal[2]) / rr)) /
      (rr * rr);
    expect(ref).toBeGreaterThan(0);
    expect(Math.abs(r.estimate - ref) / ref).toBeLessThan(1e-3);
  });
});
