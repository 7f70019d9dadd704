/**
 * Unbiasedness you can test: every correct estimator of the exam passes a t-test against its exact
 * value, and a deliberately biased variant is rejected, at α = 0.01 (Šidák-corrected over the
 * seeds of each batch), with seeded randomness and fixed sample counts.
 */
import { describe, expect, it } from 'vitest';
import { studentTTest, welchTTest, type SampleStats } from '../../../src/core/verify/ttest';
import { welchMap } from '../../../src/core/verify/welchMap';
import { estimate1D, type Problem1D } from '../../../src/core/estimators/run1d';
import { Welford } from '../../../src/core/estimators/welford';
import { linearPdf1D, uniformPdf1D } from '../../../src/core/sampling/pdf1d';
import {
  estimateAreaLight,
  type AreaLightSetup,
  type LightStrategy,
} from '../../../src/core/lights/areaLightEstimators';
import { makeRectLight } from '../../../src/core/lights/rectLight';
import { lambertianFloorRadiance } from '../../../src/core/lights/polygonIrradiance';
import { sampleRectArea } from '../../../src/core/lights/areaSampling';
import { Rng } from '../../../src/core/random/rng';

const ALPHA = 0.01;
const SEEDS = [1, 2, 3, 4, 5];

describe('Student and Welch t-tests', () => {
  it('compute t, ν and p by hand on a small example', () => {
    // x̄ = 10.5, s² = 4, N = 16: se = 0.5, t = 1 against 10, ν = 15
    const r = studentTTest({ mean: 10.5, variance: 4, n: 16 }, 10);
    expect(r.t).toBe(1);
    expect(r.dof).toBe(15);
    expect(r.pValue).toBeCloseTo(0.33317, 5); // t-table: P[|T₁₅| ≥ 1] = 0.333166
    expect(r.pass).toBe(true);
    // Welch: se² = 4/16 + 9/9 = 1.25, ν = 1.25² / (0.25²/15 + 1²/8)
    const w = welchTTest({ mean: 1, variance: 4, n: 16 }, { mean: 0, variance: 9, n: 9 });
    expect(w.t).toBeCloseTo(1 / Math.sqrt(1.25), 15);
    expect(w.dof).toBeCloseTo(1.5625 / (0.0625 / 15 + 1 / 8), 12);
  });
  it('rejects at the Šidák-corrected level and refuses what cannot be tested', () => {
    const far = studentTTest({ mean: 11.5, variance: 4, n: 16 }, 10, 0.01, 1);
    expect(far.t).toBe(3);
    expect(far.pass).toBe(far.pValue >= 0.01);
    const many = studentTTest({ mean: 11.5, variance: 4, n: 16 }, 10, 0.01, 100);
    expect(many.sidakAlpha).toBeCloseTo(1 - 0.99 ** 0.01, 15);
    expect(studentTTest({ mean: 1, variance: 1, n: 1 }, 1).pValue).toBeNaN();
    expect(studentTTest({ mean: 1, variance: 1, n: 1 }, 1).pass).toBe(false);
    expect(studentTTest({ mean: NaN, variance: 1, n: 9 }, 1).pass).toBe(false);
  });
  it('treats a zero-variance estimate as exact up to rounding', () => {
    expect(studentTTest({ mean: 19 / 3 + 1e-15, variance: 0, n: 100 }, 19 / 3).pass).toBe(true);
    expect(studentTTest({ mean: 6.4, variance: 0, n: 100 }, 19 / 3).pass).toBe(false);
    expect(welchTTest({ mean: 2, variance: 0, n: 5 }, { mean: 2, variance: 0, n: 7 }).pValue).toBe(1);
  });
});

/** The Q4 integral ∫₀¹ (x + 2)² dx = 19/3, with N independent uniforms per estimate. */
function q4(f: (x: number) => number, pdf: Problem1D['pdf'], seed: number, n = 20000): SampleStats {
  const e = estimate1D({ f, pdf, sequence: 'independent', seed }, n);
  expect(e.invalid).toBe(0);
  return { mean: e.estimate, variance: e.variance, n: e.n };
}
const f = (x: number) => (x + 2) ** 2;
const Q4 = 19 / 3;

describe('Q4: ∫₀¹ (x + 2)² dx = 19/3', () => {
  it('passes with uniform sampling and with importance sampling (p ∝ the linear ramp through f)', () => {
    for (const seed of SEEDS) {
      expect(studentTTest(q4(f, uniformPdf1D(0, 1), seed), Q4, ALPHA, SEEDS.length).pass).toBe(true);
      expect(studentTTest(q4(f, linearPdf1D(0, 1, 4, 9), seed), Q4, ALPHA, SEEDS.length).pass).toBe(true);
    }
  });
  it('rejects a clamped estimator (terms capped at 8: bias −0.085)', () => {
    const clamped = (x: number) => Math.min(f(x), 8);
    for (const seed of SEEDS) {
      const r = studentTTest(q4(clamped, uniformPdf1D(0, 1), seed), Q4, ALPHA, SEEDS.length);
      expect(r.pass).toBe(false);
      expect(r.t).toBeLessThan(0);
    }
  });
  it('Welch: uniform and importance sampling agree; the clamped one differs from both', () => {
    for (const seed of SEEDS) {
      const u = q4(f, uniformPdf1D(0, 1), seed);
      const is = q4(f, linearPdf1D(0, 1, 4, 9), seed + 100);
      const c = q4((x) => Math.min(f(x), 8), linearPdf1D(0, 1, 4, 9), seed + 200);
      expect(welchTTest(u, is, ALPHA, SEEDS.length).pass).toBe(true);
      expect(welchTTest(u, c, ALPHA, SEEDS.length).pass).toBe(false);
    }
  });
});

/** The exam's Q6 setting: a 1 × 1 light 2 above the floor, tilted 30°, L = 5, ρ = 0.8. */
const light = makeRectLight([0.4, 0.2, 2], 1, 1, 30);
const setupAt = (px: number, py: number): AreaLightSetup => ({
  light,
  occluder: null,
  px,
  py,
  pz: 0,
  L: 5,
  rho: 0.8,
});

function stats(w: Welford): SampleStats {
  return { mean: w.mean, variance: w.variance(), n: w.count };
}

/**
 * The area estimator with cos θ_l left out (a classic slip when turning p_A into solid angle):
 * terms |A| f L cos θ / r² instead of |A| f L cos θ cos θ_l / r². Biased: it over-counts a tilted light.
 */
function areaWithoutCosLight(s: AreaLightSetup, n: number, seed: number): Welford {
  const rng = new Rng(seed, 0);
  const x = new Float64Array(3);
  const w = new Welford();
  for (let i = 0; i < n; i++) {
    sampleRectArea(s.light, rng.nextFloat(), rng.nextFloat(), x, 0);
    const dx = x[0] - s.px,
      dy = x[1] - s.py,
      dz = x[2] - s.pz;
    const r2 = dx * dx + dy * dy + dz * dz;
    const cosT = dz / Math.sqrt(r2);
    w.add(cosT > 0 ? (s.light.area * (s.rho / Math.PI) * s.L * cosT) / r2 : 0);
  }
  return w;
}

describe('Q6: radiance of the floor under a rectangular light, against the polygon formula', () => {
  const points: [number, number][] = [
    [0, 0],
    [0.9, -0.4],
    [-1.2, 1.5],
  ];
  const strategies: LightStrategy[] = ['area', 'solid-angle', 'cosine'];
  const tests = points.length * strategies.length * SEEDS.length;
  it('passes area sampling (the exam’s Q6(c)) and the two other strategies', () => {
    for (const [px, py] of points) {
      const exact = lambertianFloorRadiance(light, px, py, 0, 5, 0.8);
      for (const s of strategies)
        for (const seed of SEEDS) {
          const e = estimateAreaLight(setupAt(px, py), s, 20000, seed);
          expect(studentTTest(stats(e.stats), exact, ALPHA, tests).pass).toBe(true);
        }
    }
  });
  it('rejects area sampling without cos θ_l', () => {
    for (const [px, py] of points) {
      const exact = lambertianFloorRadiance(light, px, py, 0, 5, 0.8);
      for (const seed of SEEDS) {
        const r = studentTTest(
          stats(areaWithoutCosLight(setupAt(px, py), 20000, seed)),
          exact,
          ALPHA,
          points.length * SEEDS.length,
        );
        expect(r.pass).toBe(false);
      }
    }
  });
});

describe('Welch t-test map over two floor images', () => {
  const size = 8;
  const spp = 256;
  function image(render: (s: AreaLightSetup, seed: number) => Welford, seed: number) {
    const mean = new Float64Array(size * size);
    const variance = new Float64Array(size * size);
    const count = new Float64Array(size * size);
    for (let j = 0; j < size; j++)
      for (let i = 0; i < size; i++) {
        const k = j * size + i;
        const w = render(
          setupAt(-1.5 + (3 * (i + 0.5)) / size, 1.5 - (3 * (j + 0.5)) / size),
          seed * 1000 + k,
        );
        mean[k] = w.mean;
        variance[k] = w.variance();
        count[k] = w.count;
      }
    return { mean, variance, count };
  }
  const by = (st: LightStrategy) => (s: AreaLightSetup, seed: number) =>
    estimateAreaLight(s, st, spp, seed).stats;
  it('finds area and solid-angle sampling converging to the same image', () => {
    const m = welchMap(image(by('area'), 1), image(by('solid-angle'), 2), ALPHA);
    expect(m.tested).toBe(size * size);
    expect(m.sidakAlpha).toBeCloseTo(1 - (1 - ALPHA) ** (1 / 64), 15);
    expect(m.rejected).toBe(0);
    expect(m.pass).toBe(true);
  });
  it('finds the estimator without cos θ_l biased, and says where', () => {
    const m = welchMap(
      image(by('solid-angle'), 3),
      image((s, seed) => areaWithoutCosLight(s, spp, seed), 4),
      ALPHA,
    );
    expect(m.pass).toBe(false);
    expect(m.rejected).toBeGreaterThan(0);
    expect(m.minP).toBeLessThan(m.sidakAlpha);
  });
  it('refuses images of different sizes and skips pixels with too few samples', () => {
    const a = { mean: [1, 2], variance: [1, 1], count: [4, 1] };
    expect(() => welchMap(a, { mean: [1], variance: [1], count: [4] })).toThrow(RangeError);
    const m = welchMap(a, a);
    expect(m.tested).toBe(1);
    expect(m.pValues[1]).toBeNaN();
  });
});
