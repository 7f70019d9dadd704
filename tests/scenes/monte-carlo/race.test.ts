/**
 * The animation's model: what is on screen at position t is a pure function of
 * (f, [a, b], pdf, seed, t), a prefix of one seeded stream; checked against a direct recomputation.
 */
import { describe, expect, it } from 'vitest';
import { Rng } from '../../../src/core/random/rng';
import {
  customPdf1D,
  linearPdf1D,
  proportionalPdf1D,
  squarePdf1D,
  uniformPdf1D,
  type Pdf1D,
} from '../../../src/core/sampling/pdf1d';
import { atRoundingLevel } from '../../../src/scenes/monte-carlo/zeroVariance';
import { RACE_STREAM, raceAt, racePoints, raceTrack } from '../../../src/scenes/monte-carlo/race';
import { sortedByX } from '../../../src/scenes/monte-carlo/compared';
import { squareAntiderivative, squareNormalizer } from '../../../src/scenes/monte-carlo/exam';
import { stderrIsValid } from '../../../src/scenes/monte-carlo/drawnEstimate';

const f = (x: number) => (x + 2) ** 2;
const I = (4 ** 3 - 2 ** 3) / 3;

function direct(seed: number, t: number) {
  const rng = new Rng(seed, RACE_STREAM);
  const xi = Array.from({ length: t }, () => rng.nextFloat());
  const p = squarePdf1D(0, 2, 2);
  const tu = xi.map((u) => 2 * f(2 * u));
  const ti = xi.map((u) => {
    const x = p.sample(u);
    return f(x) / p.pdf(x);
  });
  const stats = (ys: number[]) => {
    const m = ys.reduce((s, y) => s + y, 0) / ys.length;
    const v = ys.reduce((s, y) => s + (y - m) ** 2, 0) / (ys.length - 1);
    return { m, se: Math.sqrt(v / ys.length) };
  };
  return { xu: 2 * xi[t - 1], u: stats(tu), i: stats(ti), lastTermU: tu[t - 1] };
}

describe('race model', () => {
  const track = raceTrack(f, 0, 2, squarePdf1D(0, 2, 2), I, 7, 2000);

  it('the frame at t equals a direct recomputation from the seeded stream', () => {
    for (const t of [2, 3, 17, 500, 2000]) {
      const fr = raceAt(track, t);
      const d = direct(7, t);
      expect(fr.uniform.n).toBe(t);
      expect(fr.uniform.x).toBeCloseTo(d.xu, 14);
      expect(fr.uniform.term).toBeCloseTo(d.lastTermU, 12);
      expect(Math.abs(fr.uniform.estimate - d.u.m)).toBeLessThan(1e-11);
      expect(Math.abs(fr.uniform.stderr - d.u.se)).toBeLessThan(1e-9);
      expect(Math.abs(fr.importance.estimate - I)).toBeLessThan(1e-12);
      expect(fr.importance.stderr).toBeLessThan(1e-12);
      expect(fr.uniform.absError).toBeCloseTo(Math.abs(d.u.m - I), 10);
    }
  });

  it('is a prefix of a longer track, deterministic, and changes with the seed', () => {
    const longer = raceTrack(f, 0, 2, squarePdf1D(0, 2, 2), I, 7, 4000);
    const a = raceAt(track, 1234);
    const b = raceAt(longer, 1234, racePoints(2000));
    expect(b.uniform).toEqual(a.uniform);
    expect(b.curve).toEqual(a.curve);
    expect(raceAt(raceTrack(f, 0, 2, squarePdf1D(0, 2, 2), I, 7, 2000), 1234)).toEqual(a);
    expect(raceAt(raceTrack(f, 0, 2, squarePdf1D(0, 2, 2), I, 8, 2000), 1234).uniform.x).not.toBe(
      a.uniform.x,
    );
  });

  it('both lanes use the same ξᵢ: the importance x is P⁻¹ of the uniform lane’s ξ', () => {
    const p = squarePdf1D(0, 2, 2);
    for (let k = 0; k < 50; k++)
      expect(track.importance.x[k]).toBeCloseTo(p.sample(track.uniform.x[k] / 2), 12);
  });

  it('t = 0 shows nothing; t is clamped; curves grow with t and end at t', () => {
    const z = raceAt(track, 0);
    expect(z.uniform.n).toBe(0);
    expect(Number.isNaN(z.uniform.estimate)).toBe(true);
    expect(z.curve.n).toEqual([]);
    expect(raceAt(track, 1e9).t).toBe(2000);
    const fr = raceAt(track, 777);
    expect(fr.curve.n.at(-1)).toBe(777);
    expect(fr.curve.n.every((n, k) => k === 0 || n > fr.curve.n[k - 1])).toBe(true);
    expect(fr.recentU.length).toBe(40);
    expect(fr.recentU.at(-1)).toBe(fr.uniform.x);
  });

  it('a uniform importance pdf reproduces the uniform lane', () => {
    const t2 = raceTrack(f, 0, 2, uniformPdf1D(0, 2), I, 3, 100);
    for (let k = 0; k < 100; k++)
      expect(Math.abs(t2.importance.mean[k] - t2.uniform.mean[k])).toBeLessThan(1e-11);
  });
});

/** The track computed sample by sample (nextFloat, sample, pdf, Welford), the plain way. */
function plainTrack(g: (x: number) => number, a: number, b: number, imp: Pdf1D, seed: number, max: number) {
  const rng = new Rng(seed, RACE_STREAM);
  const xi = Array.from({ length: max }, () => rng.nextFloat());
  const lane = (xs: number[], terms: number[]) => {
    let mean = 0;
    let m2 = 0;
    const means: number[] = [];
    const m2s: number[] = [];
    terms.forEach((y, i) => {
      const d = y - mean;
      mean += d / (i + 1);
      m2 += d * (y - mean);
      means.push(mean);
      m2s.push(m2);
    });
    return { x: xs, term: terms, mean: means, m2: m2s };
  };
  const xu = xi.map((u) => a + (b - a) * u);
  const xs = xi.map((u) => imp.sample(u));
  return {
    xi,
    uniform: lane(
      xu,
      xu.map((x) => (b - a) * g(x)),
    ),
    importance: lane(
      xs,
      xs.map((x) => {
        const fx = g(x);
        return fx === 0 ? 0 : fx / imp.pdf(x);
      }),
    ),
  };
}

describe('raceTrack equals the plain per-sample computation exactly', () => {
  const g = (x: number) => Math.exp(x) * Math.sin(3 * x) + 1.5;
  const custom = customPdf1D((x) => 1 + x * x, -1, 2, g);
  const prop = proportionalPdf1D(g, -1, 2);
  if (!custom.ok || !prop.ok) throw new Error('test pdfs');
  const cases: [string, (x: number) => number, number, number, Pdf1D][] = [
    ['square', f, 0, 2, squarePdf1D(0, 2, 2)],
    ['square, shifted', (x) => (x - 1) * (x - 1), -1, 3, squarePdf1D(-1, 3, -1)],
    ['linear', g, -1, 2, linearPdf1D(-1, 2, 0.5, 3)],
    ['linear from 0', g, -1, 2, linearPdf1D(-1, 2, 0, 3)],
    ['tabulated p ∝ |f|', g, -1, 2, prop.pdf],
    ['custom', g, -1, 2, custom.pdf],
    ['uniform', g, -1, 2, uniformPdf1D(-1, 2)],
  ];
  for (const [name, g1, a, b, imp] of cases) {
    it(name, () => {
      const want = plainTrack(g1, a, b, imp, 5, 3000);
      const got = raceTrack(g1, a, b, imp, 1, 5, 3000);
      expect(Array.from(got.xi)).toEqual(want.xi);
      for (const lane of ['uniform', 'importance'] as const) {
        for (const k of ['x', 'term', 'mean', 'm2'] as const)
          expect(Array.from(got[lane][k]), `${lane}.${k}`).toEqual(want[lane][k]);
      }
    });
  }
});

describe('Q4 helpers', () => {
  it('the antiderivative of (x + 2)² on [0, 2] gives 56/3 term by term', () => {
    const r = squareAntiderivative(2, 0, 2);
    expect(r.Fb.cube).toBeCloseTo(8 / 3, 14);
    expect(r.Fb.lin2).toBe(8);
    expect(r.Fb.lin).toBe(8);
    expect(r.valueA).toBe(0);
    expect(r.value).toBeCloseTo(56 / 3, 13);
    expect(squareNormalizer(2, 0, 2)).toBe(56);
    // another (x + c)² against direct quadrature of the expansion
    const s = squareAntiderivative(-1.5, -1, 3);
    expect(s.value).toBeCloseTo(((3 - 1.5) ** 3 - (-1 - 1.5) ** 3) / 3, 12);
  });

  it('stderr validity, rounding-level test and sorting by x', () => {
    expect(stderrIsValid('independent')).toBe(true);
    for (const s of ['stratified', 'halton', 'sobol'] as const) expect(stderrIsValid(s)).toBe(false);
    expect(atRoundingLevel([0, 1e-15, NaN], 18)).toBe(true);
    expect(atRoundingLevel([0, 1e-3], 18)).toBe(false);
    expect(atRoundingLevel([NaN], 18)).toBe(false);
    expect(sortedByX([{ x: 3 }, { x: 1 }, { x: 2 }]).map((p) => p.x)).toEqual([1, 2, 3]);
  });
});
