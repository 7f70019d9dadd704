/**
 * Every hemisphere warp through one table, as Mitsuba 3's `check_inverse` / `test_warp.py` and
 * Nori's `warptest` do: for each row the same checks run —
 *  - stress inputs ξ ∈ {0, 2⁻⁵³, ½, 1 − 2⁻⁵³}²: finite unit vectors with z ≥ 0, finite pdf ≥ 0,
 *    and the inverse lands in [0, 1)²;
 *  - round trip invert(sample(ξ)) ≈ ξ (fast-check property, or a grid where the row asks);
 *  - the batch kernel equals the scalar sampler (bit for bit unless the row says otherwise);
 *  - χ² (core/verify, α = 0.01, Šidák-corrected) accepts the sampler against its own pdf, and
 *    rejects the row's deliberately broken variants.
 * Checks that belong to one warp only (60-digit references, normalization, moments, pdf values)
 * follow the table. Source: Mitsuba 3 `src/core/python/tests/test_warp.py`, pbrt-v4 `sampling_test.cpp`.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { hemisphereChi2, type HemisphereChi2Options } from '../../../src/core/verify';
import { Rng, fillSequence2D } from '../../../src/core/random';
import {
  EXAM_E2PI_M1,
  cosineHemispherePdf,
  examLobePdf,
  invertCosineHemisphereSample,
  invertExamLobeSample,
  invertPhongLobeSample,
  invertUniformDiskConcentricSample,
  invertUniformHemisphereSample,
  phongLobePdf,
  phongThetaCdf,
  phongThetaPdf,
  sampleCosineHemisphere,
  sampleCosineHemisphereBatch,
  sampleExamLobe,
  sampleExamLobeBatch,
  samplePhongLobe,
  samplePhongLobeBatch,
  sampleUniformDiskConcentric,
  sampleUniformHemisphere,
  sampleUniformHemisphereBatch,
  tabulateHemisphereDensity,
  uniformHemispherePdf,
  type TabulatedHemisphere,
  type VecOut,
} from '../../../src/core/sampling';
import { STRESS_PAIRS, norm3, torusDist } from './stress';

type Dir = [number, number, number];
type BatchFn = (u: Float64Array, out: Float64Array, n: number) => void;

interface Warp {
  name: string;
  sample: (u1: number, u2: number, out: VecOut, o?: number) => void;
  sampleBatch: BatchFn;
  pdf: (x: number, y: number, z: number) => number;
  invert: (x: number, y: number, z: number) => [number, number];
  /** Bound on | |ω| − 1 | at the stress inputs. */
  normTol: number;
  /** Extra checks at each stress pair (after sampling into `dir`). */
  stressExtra?: (a: number, b: number, dir: Dir, u: [number, number]) => void;
  /** Does (u1, u2) = invert(sample(a, b)) count as a round trip? */
  roundTrip: (a: number, b: number, u1: number, u2: number, dir: Dir) => boolean;
  /** fast-check runs and seed; `grid` instead samples a 33 × 33 grid. */
  property: { numRuns: number; seed: number } | 'grid';
  /** Batch = scalar tolerance (0: bit for bit), and the seed of the uniforms. */
  batch: { tol: number; seed: number; n: number };
  /** χ² acceptance: sample count, seed, options (absent: covered by another row of the lobe). */
  chi2?: { n: number; seed: number; opts: HemisphereChi2Options };
  /** Deliberately broken samplers χ² must reject (against this row's pdf unless given). */
  broken?: { name: string; sampleBatch: BatchFn; pdf?: Warp['pdf']; seed: number; maxP?: number }[];
}

const unit = fc.double({ min: 0, max: 1, maxExcluded: true, noNaN: true });
const N = 200_000;
const SIDAK = { tests: 6, cosThetaBins: 10, phiBins: 20 }; // the analytic warps' acceptance tests (Šidák)

function tabulated(p: (t: number, f: number) => number): TabulatedHemisphere {
  const r = tabulateHemisphereDensity(p);
  if (!r.ok) throw new Error(r.message);
  return r.lobe;
}

function phongRow(n: number, chi2Seed?: number): Warp {
  return {
    name: `Phong n = ${n}`,
    sample: (a, b, out, o) => samplePhongLobe(a, b, n, out, o),
    sampleBatch: (u, out, c) => samplePhongLobeBatch(u, n, out, c),
    pdf: (x, y, z) => phongLobePdf(x, y, z, n),
    invert: (x, y, z) => invertPhongLobeSample(x, y, z, n),
    normTol: 1e-15,
    roundTrip: (a, b, u1, u2, d) =>
      Math.abs(u1 - a) < 1e-9 && (Math.hypot(d[0], d[1]) < 1e-6 || torusDist(u2, b) < 1e-9),
    property: { numRuns: 400, seed: 8 },
    batch: { tol: 0, seed: 4, n: 500 },
    chi2: chi2Seed === undefined ? undefined : { n: N, seed: chi2Seed, opts: SIDAK },
  };
}

function tabulatedRow(label: string, p: (t: number, f: number) => number, chi2Seed: number): Warp {
  const lobe = tabulated(p);
  return {
    name: `tabulated ${label}`,
    sample: (a, b, out, o) => lobe.sample(a, b, out, o),
    sampleBatch: (u, out, n) => lobe.sampleBatch(u, out, n),
    pdf: (x, y, z) => lobe.pdf(x, y, z),
    invert: (x, y, z) => lobe.invert(x, y, z),
    normTol: 1e-15,
    roundTrip: (a, b, u1, u2) => Math.abs(u1 - a) < 1e-9 && Math.abs(u2 - b) < 1e-7,
    property: { numRuns: 700, seed: 17 },
    batch: { tol: 1e-14, seed: 6, n: 500 },
    chi2: { n: 100_000, seed: chi2Seed, opts: {} },
  };
}

const WARPS: Warp[] = [
  {
    name: 'exam lobe k cos θ e^φ',
    sample: sampleExamLobe,
    sampleBatch: sampleExamLobeBatch,
    pdf: examLobePdf,
    invert: invertExamLobeSample,
    normTol: 2e-16 * 4,
    stressExtra: (a, b, _d, [u1, u2]) => {
      expect(Math.abs(u1 - a)).toBeLessThan(4e-16);
      if (a > 0) expect(torusDist(u2, b)).toBeLessThan(1e-12);
    },
    roundTrip: (a, b, u1, u2) => {
      const ok1 = Math.abs(u1 - a) <= 4e-16 * Math.max(1, a) + 1e-300;
      const ok2 = a < 1e-300 || torusDist(u2, b) < 1e-12 * (1 + 600 * b);
      return ok1 && (ok2 || a === 0);
    },
    property: { numRuns: 3000, seed: 42 },
    batch: { tol: 0, seed: 21, n: 2000 },
    chi2: { n: N, seed: 1, opts: SIDAK },
    broken: [
      {
        name: 'a missing square root (sin θ = ξ₁ instead of √ξ₁)',
        seed: 11,
        maxP: 1e-10,
        sampleBatch: (u, o, n) => {
          for (let i = 0; i < n; i++) {
            const s = u[2 * i];
            const phi = Math.log1p(EXAM_E2PI_M1 * u[2 * i + 1]);
            o[3 * i] = s * Math.cos(phi);
            o[3 * i + 1] = s * Math.sin(phi);
            o[3 * i + 2] = Math.sqrt(1 - s * s);
          }
        },
      },
      {
        name: 'a wrong exponent in φ (P(φ) from e^{2φ})',
        seed: 12,
        sampleBatch: (u, o, n) => {
          const c2 = Math.expm1(4 * Math.PI);
          for (let i = 0; i < n; i++) {
            const s = Math.sqrt(u[2 * i]);
            const phi = 0.5 * Math.log1p(c2 * u[2 * i + 1]);
            o[3 * i] = s * Math.cos(phi);
            o[3 * i + 1] = s * Math.sin(phi);
            o[3 * i + 2] = Math.sqrt(1 - u[2 * i]);
          }
        },
      },
    ],
  },
  {
    name: 'uniform hemisphere',
    sample: sampleUniformHemisphere,
    sampleBatch: sampleUniformHemisphereBatch,
    pdf: uniformHemispherePdf,
    invert: invertUniformHemisphereSample,
    normTol: 1e-15,
    stressExtra: (_a, _b, d) =>
      expect(uniformHemispherePdf(d[0], d[1], d[2])).toBeCloseTo(1 / (2 * Math.PI), 15),
    // near the pole the azimuth is undefined: only check u2 where sin θ is not tiny
    roundTrip: (a, b, u1, u2) => Math.abs(u1 - a) < 1e-12 && (a > 1 - 1e-8 || torusDist(u2, b) < 1e-9),
    property: { numRuns: 2000, seed: 7 },
    batch: { tol: 0, seed: 3, n: 1000 },
    chi2: { n: N, seed: 2, opts: SIDAK },
    broken: [
      {
        name: 'tested against the cosine pdf',
        seed: 14,
        sampleBatch: sampleUniformHemisphereBatch,
        pdf: cosineHemispherePdf,
      },
    ],
  },
  {
    name: 'cosine hemisphere (concentric)',
    sample: sampleCosineHemisphere,
    sampleBatch: sampleCosineHemisphereBatch,
    pdf: cosineHemispherePdf,
    invert: invertCosineHemisphereSample,
    normTol: 1e-15,
    roundTrip: (a, b, u1, u2) => Math.abs(u1 - a) < 1e-12 && Math.abs(u2 - b) < 1e-12,
    property: 'grid',
    batch: { tol: 0, seed: 9, n: 1000 },
    chi2: { n: N, seed: 3, opts: SIDAK },
  },
  ...[0, 1, 100, 1e4].map((n) => phongRow(n)),
  {
    ...phongRow(8, 4),
    broken: [
      {
        name: 'exponent n + 1 tested against the pdf for n',
        seed: 13,
        sampleBatch: (u, out, n) => samplePhongLobeBatch(u, 9, out, n),
      },
    ],
  },
  phongRow(50, 5),
  tabulatedRow('cos θ e^φ', (t, f) => Math.cos(t) * Math.exp(f), 7),
  tabulatedRow('cos θ (2 + cos φ)', (t, f) => Math.cos(t) * (2 + Math.cos(f)), 8),
  tabulatedRow(
    'cos²θ (1.5 + sin(2φ + 3θ)) (non-separable)',
    (t, f) => Math.cos(t) ** 2 * (1.5 + Math.sin(2 * f + 3 * t)),
    5,
  ),
];

describe.each(WARPS)('warp: $name', (w) => {
  it('stress inputs: finite unit vectors with z ≥ 0, finite pdf ≥ 0, inverse in [0, 1)²', () => {
    const out = new Float64Array(3);
    for (const [a, b] of STRESS_PAIRS) {
      w.sample(a, b, out);
      expect(out.every(Number.isFinite)).toBe(true);
      expect(out[2]).toBeGreaterThanOrEqual(0);
      expect(Math.abs(norm3(out) - 1)).toBeLessThan(w.normTol);
      const pdf = w.pdf(out[0], out[1], out[2]);
      expect(Number.isFinite(pdf)).toBe(true);
      expect(pdf).toBeGreaterThanOrEqual(0);
      const u = w.invert(out[0], out[1], out[2]);
      for (const v of u) {
        expect(v).toBeGreaterThanOrEqual(0);
        expect(v).toBeLessThan(1);
      }
      w.stressExtra?.(a, b, [out[0], out[1], out[2]], u);
    }
  });

  it('round trip invert(sample(ξ)) ≈ ξ', () => {
    const out: Dir = [0, 0, 0];
    const check = (a: number, b: number): boolean => {
      w.sample(a, b, out);
      const [u1, u2] = w.invert(out[0], out[1], out[2]);
      return w.roundTrip(a, b, u1, u2, out);
    };
    if (w.property === 'grid') {
      for (let i = 0; i < 33; i++)
        for (let j = 0; j < 33; j++) {
          const a = (i + 0.37) / 33;
          const b = (j + 0.61) / 33;
          expect(check(a, b), `ξ = (${a}, ${b})`).toBe(true);
        }
    } else fc.assert(fc.property(unit, unit, check), w.property);
  });

  it('batch kernel equals the scalar sampler (stress inputs included)', () => {
    const { n, seed, tol } = w.batch;
    const u = new Rng(seed).fill(new Float64Array(2 * n));
    STRESS_PAIRS.forEach(([a, b], i) => {
      u[2 * i] = a;
      u[2 * i + 1] = b;
    });
    const out = new Float64Array(3 * n);
    w.sampleBatch(u, out, n);
    const one = new Float64Array(3);
    for (let i = 0; i < n; i++) {
      w.sample(u[2 * i], u[2 * i + 1], one);
      for (let c = 0; c < 3; c++) {
        if (tol === 0) expect(out[3 * i + c]).toBe(one[c]);
        else expect(Math.abs(out[3 * i + c] - one[c])).toBeLessThan(tol);
      }
    }
  });

  it.runIf(w.chi2 !== undefined)('χ² accepts the sampler against its own pdf', () => {
    const { n, seed, opts } = w.chi2!;
    const out = new Float64Array(3 * n);
    w.sampleBatch(fillSequence2D('independent', seed, n, new Float64Array(2 * n)), out, n);
    const r = hemisphereChi2(out, n, w.pdf, opts);
    expect(r.outside).toBe(0);
    expect(r.pass).toBe(true);
  });

  it.each(w.broken ?? [])('χ² rejects a broken variant: $name', (b) => {
    const out = new Float64Array(3 * N);
    b.sampleBatch(fillSequence2D('independent', b.seed, N, new Float64Array(2 * N)), out, N);
    const r = hemisphereChi2(out, N, b.pdf ?? w.pdf, SIDAK);
    expect(r.pass).toBe(false);
    if (b.maxP !== undefined) expect(r.pValue).toBeLessThan(b.maxP);
  });
});

it('χ² accepts the exam lobe with Sobol points too (marginals stay exact)', () => {
  const out = new Float64Array(3 * N);
  sampleExamLobeBatch(fillSequence2D('sobol', 9, N, new Float64Array(2 * N)), out, N);
  expect(hemisphereChi2(out, N, examLobePdf, { tests: SIDAK.tests }).pass).toBe(true);
});

/** Moments: E[cos θ] for the lobes with a closed form, within 4σ. */
describe.each([
  { name: 'uniform', sample: sampleUniformHemisphere, seed: 11, n: 200000, mean: 1 / 2, sigma2: 1 / 12 },
  { name: 'cosine', sample: sampleCosineHemisphere, seed: 12, n: 200000, mean: 2 / 3 },
  {
    name: 'Phong n = 8',
    sample: (a: number, b: number, o: VecOut) => samplePhongLobe(a, b, 8, o),
    seed: 5,
    n: 100000,
    mean: 9 / 10,
  },
])('E[cos θ] of the $name lobe', ({ sample, seed, n, mean, sigma2 }) => {
  it(`is ${mean.toFixed(4)} within 4σ`, () => {
    const rng = new Rng(seed);
    const out = [0, 0, 0];
    let s = 0;
    let s2 = 0;
    for (let i = 0; i < n; i++) {
      sample(rng.nextFloat(), rng.nextFloat(), out);
      s += out[2];
      s2 += out[2] * out[2];
    }
    const m = s / n;
    const sigma = Math.sqrt((sigma2 ?? s2 / n - m * m) / n);
    expect(Math.abs(m - mean)).toBeLessThan(4 * sigma);
  });
});

describe('pdf values (direction (x, y, z); only z matters for these lobes)', () => {
  it('uniform: 0 below the horizon and for NaN, constant above', () => {
    expect(uniformHemispherePdf(0, 0, -1e-300)).toBe(0);
    expect(uniformHemispherePdf(0, 0, -1)).toBe(0);
    expect(uniformHemispherePdf(0, 0, Number.NaN)).toBe(0);
    expect(uniformHemispherePdf(0, 0, 0.3)).toBe(1 / (2 * Math.PI));
  });
  it('cosine: cos θ/π, 0 below the horizon and for NaN', () => {
    expect(cosineHemispherePdf(0, 0, 1)).toBe(1 / Math.PI);
    expect(cosineHemispherePdf(0, 0, 0.5)).toBeCloseTo(0.5 / Math.PI, 16);
    expect(cosineHemispherePdf(0, 0, -0.2)).toBe(0);
    expect(cosineHemispherePdf(0, 0, Number.NaN)).toBe(0);
  });
  it('Phong: n = 0 is uniform, n = 1 the cosine lobe; 0 below the horizon and for NaN', () => {
    expect(phongLobePdf(0, 0, 0.3, 0)).toBeCloseTo(1 / (2 * Math.PI), 15);
    expect(phongLobePdf(0, 0, 0.3, 1)).toBeCloseTo(0.3 / Math.PI, 15);
    expect(phongLobePdf(0, 0, -0.1, 8)).toBe(0);
    expect(phongLobePdf(0, 0, Number.NaN, 8)).toBe(0);
    expect(phongThetaPdf(2, 8)).toBe(0);
  });
});

function simpson(f: (x: number) => number, a: number, b: number, n = 4000): number {
  const h = (b - a) / n;
  let s = f(a) + f(b);
  for (let i = 1; i < n; i++) s += (i % 2 ? 4 : 2) * f(a + i * h);
  return (s * h) / 3;
}

it('Phong: ∫ p dω = 1, the θ marginal integrates to 1, its CDF is its integral', () => {
  for (const n of [0, 1, 8, 100]) {
    const v =
      2 *
      Math.PI *
      simpson((t) => phongLobePdf(Math.sin(t), 0, Math.cos(t), n) * Math.sin(t), 0, Math.PI / 2);
    expect(v).toBeCloseTo(1, 8);
    expect(simpson((t) => phongThetaPdf(t, n), 0, Math.PI / 2)).toBeCloseTo(1, 8);
    for (const t of [0.05, 0.3, 1.2])
      expect(phongThetaCdf(t, n)).toBeCloseTo(
        simpson((s) => phongThetaPdf(s, n), 0, t),
        8,
      );
  }
});

it('concentric disk map stays inside the unit disk and round-trips (property)', () => {
  const d = [0, 0];
  fc.assert(
    fc.property(unit, unit, (a, b) => {
      sampleUniformDiskConcentric(a, b, d);
      if (Math.hypot(d[0], d[1]) > 1 + 1e-15) return false;
      const [u1, u2] = invertUniformDiskConcentricSample(d[0], d[1]);
      // at the centre every (u1,u2) near (½,½) maps to ~0: the inverse is only defined up to r
      const r = Math.hypot(2 * a - 1, 2 * b - 1);
      const tol = r < 1e-9 ? 1e-8 : 1e-9;
      return Math.abs(u1 - a) < tol && Math.abs(u2 - b) < tol;
    }),
    { numRuns: 3000, seed: 5 },
  );
});
