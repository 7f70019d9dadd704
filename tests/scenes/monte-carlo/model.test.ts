import { formatCount } from '../../../src/ui/format';
import { describe, expect, it } from 'vitest';
import { EXAM_SAMPLES, KEY_PRINTED, keyComparison, roundTo } from '../../../src/scenes/monte-carlo/exam';
import { checkLimits, exactIntegral, squareShift } from '../../../src/scenes/monte-carlo/integral';
import { choosePdf } from '../../../src/scenes/monte-carlo/pdfChoice';
import { curves } from '../../../src/scenes/monte-carlo/curves';
import { sampleTable } from '../../../src/scenes/monte-carlo/sampleTable';
import { histogram } from '../../../src/core/estimators';
import { compileX } from '../../../src/scenes/monte-carlo/expr';
import {
  convergenceJob,
  estimateJob,
  histogramJob,
  rmseJob,
  type ProblemArgs,
} from '../../../src/scenes/monte-carlo/jobs';
import { parseParams } from '../../../src/kit/params';
import { schema } from '../../../src/scenes/monte-carlo/params';

const f = (x: number) => (x + 2) ** 2;
const I = 56 / 3;

describe('model', () => {
  it('recognizes (x + c)² sources', () => {
    expect(squareShift('(x+2)^2')).toBe(2);
    expect(squareShift(' ( x + 2 ) ** 2 ')).toBe(2);
    expect(squareShift('(x-0.5)^2')).toBe(-0.5);
    expect(squareShift('x^2')).toBe(0);
    expect(squareShift('(x+2)^3')).toBeNull();
    expect(squareShift('sin(x)')).toBeNull();
  });

  it('exact integral: closed form for the exam, Gauss–Kronrod otherwise, problems named', () => {
    expect(exactIntegral('(x+2)^2', f, 0, 2).value).toBe(I);
    const g = exactIntegral('exp(x)', Math.exp, -1, 1);
    expect(g.value).toBeCloseTo(Math.E - 1 / Math.E, 14);
    expect(g.method).toMatch(/Gauss–Kronrod/);
    expect(exactIntegral('sqrt(x)', Math.sqrt, -1, 1).problem).toMatch(/not finite/);
  });

  it('worked Q4 table: uniform ≈ 21.45 from the formula, p ∝ f exactly 56/3', () => {
    const u = choosePdf('uniform', '(x+2)^2', f, 0, 2, null);
    const p = choosePdf('proportional', '(x+2)^2', f, 0, 2, null);
    if (!u.ok || !p.ok) throw new Error('pdfs');
    const t = sampleTable(EXAM_SAMPLES, f, 0, 2, u.density, p.density);
    const byHand = EXAM_SAMPLES.reduce((s, x) => s + (x + 2) ** 2 / 0.5, 0) / 4;
    expect(t.uniform.estimate).toBeCloseTo(byHand, 12);
    expect(t.chosen!.estimate).toBeCloseTo(byHand, 12);
    expect(t.rows.map((r) => r.p)).toEqual([0.5, 0.5, 0.5, 0.5]);
    expect(t.proportional!.estimate).toBeCloseTo(I, 13);
    expect(t.proportional!.variance).toBeLessThan(1e-25);
    expect(t.problems).toEqual([]);
  });

  it('key comparison flags the printed intermediates that differ from the computation', () => {
    const u = choosePdf('uniform', '(x+2)^2', f, 0, 2, null);
    if (!u.ok) throw new Error('pdf');
    const t = sampleTable(EXAM_SAMPLES, f, 0, 2, u.density, null);
    const notes = keyComparison('(x+2)^2', 0, 2, EXAM_SAMPLES, t);
    expect(notes).toHaveLength(5);
    for (const [i, x] of EXAM_SAMPLES.entries()) {
      expect(notes[i].computed).toBeCloseTo((x + 2) ** 2, 13);
      expect(notes[i].agrees).toBe(roundTo((x + 2) ** 2, 2) === KEY_PRINTED.f[i]);
    }
    // (1.16+2)² = 9.9856 rounds to 9.99, not 9.98; 0.54 → 6.4516 → 6.45 agrees
    expect(notes[0].agrees).toBe(false);
    expect(notes[2].agrees).toBe(true);
    expect(notes[4].agrees).toBe(true); // the final 21.45 is right
    expect(keyComparison('(x+2)^2', 0, 3, EXAM_SAMPLES, t)).toEqual([]);
  });

  it('given samples outside [a, b] are reported, not averaged in', () => {
    const u = choosePdf('uniform', 'x', (x) => x, 0, 1, null);
    if (!u.ok) throw new Error('pdf');
    const t = sampleTable([0.5, 3], (x) => x, 0, 1, u.density, null);
    expect(t.problems[0]?.message).toMatch(/outside/);
    expect(t.chosen!.invalid).toBe(1);
    expect(t.chosen!.estimate).toBe(0.5);
  });

  it('bad pdfs give messages; linear needs a nonzero end', () => {
    const neg = choosePdf('custom', '(x+2)^2', f, 0, 2, (x) => x - 1);
    expect(neg.ok).toBe(false);
    if (!neg.ok) expect(neg.message).toMatch(/negative/);
    const lin = choosePdf('linear', 'x*(1-x)', (x) => x * (1 - x), 0, 1, null);
    expect(lin.ok).toBe(false);
    expect(choosePdf('custom', 'x', (x) => x, 0, 1, null).ok).toBe(false);
    expect(checkLimits(2, 1).message).toMatch(/a < b/);
    expect(checkLimits(2, 1).problem?.name).toBe('b');
    expect(checkLimits(0, 1).problem).toBeNull();
  });

  it('curves and histogram', () => {
    const c = curves(f, (x) => (3 / 56) * f(x), 0, 2, 11);
    expect(c.f[10]).toBe(16);
    expect(Math.abs(c.p[10] - 16)).toBeLessThan(0.1);
    const h = histogram([1, 2, 2, 3, NaN], 2);
    expect(Array.from(h.counts)).toEqual([1, 3]);
    expect(histogram([5, 5], 3).counts.reduce((s, v) => s + v, 0)).toBe(2);
  });

  it('URL schema: samples list and defaults parse', () => {
    const p = parseParams(schema, 'samples=1.16,1.98,0.54,1.26&pdf=proportional&n=abc');
    expect(p.values.samples).toEqual(EXAM_SAMPLES);
    expect(p.values.pdf).toBe('proportional');
    expect(p.values.n).toBe(10000);
    expect(p.problems.some((q) => q.name === 'n')).toBe(true);
  });
});

describe('jobs (as run in the worker)', () => {
  const base: ProblemArgs = {
    f: '(x+2)^2',
    a: 0,
    b: 2,
    pdfexpr: '1 + x',
    seed: 3,
    strategies: [
      { pdf: 'uniform', seq: 'independent', label: 'u' },
      { pdf: 'proportional', seq: 'independent', label: 'p' },
      { pdf: 'custom', seq: 'sobol', label: 'c' },
    ],
  };

  it('convergence: p ∝ f is exact at every N; uniform within 5σ; partials arrive', async () => {
    const partials: unknown[] = [];
    const r = await convergenceJob({ ...base, nMax: 20000 }, compileX, (_, p) => partials.push(p), 0);
    expect(r.exact).toBe(I);
    const [u, p, c] = r.series;
    expect(u!.recorded).toBe(u!.n.length);
    const k = u!.recorded - 1;
    expect(Math.abs(u!.estimate[k] - I)).toBeLessThan(5 * u!.stderr[k]);
    for (const e of p!.absError) expect(e).toBeLessThan(1e-12);
    expect(Math.abs(c!.estimate[c!.recorded - 1] - I)).toBeLessThan(0.05);
    expect(partials.length).toBeGreaterThan(0);
  });

  it('rmse: times are measured, p ∝ f has ~zero RMSE, uniform slope ≈ −1/2', async () => {
    const r = await rmseJob(
      { ...base, strategies: base.strategies.slice(0, 2), nMax: 2000, runs: 24 },
      compileX,
    );
    const [u, p] = r.rmse;
    expect(u!.runs).toBe(24);
    expect(Math.abs(u!.slope + 0.5)).toBeLessThan(0.2);
    expect(Math.max(...p!.rmse)).toBeLessThan(1e-12);
    expect(u!.timeMs.every((t) => t >= 0)).toBe(true);
  });

  it('histogram: mean of many estimates ≈ the integral (unbiasedness)', async () => {
    const r = await histogramJob({ ...base, strategies: [base.strategies[0]], N: 8, M: 2000 }, compileX);
    let s = 0;
    for (const e of r.estimates) s += e;
    const mean = s / r.estimates.length;
    // σ of one 8-sample estimate ≈ 7.14/√8 ≈ 2.5; of the mean of 2000 ≈ 0.056
    expect(Math.abs(mean - I)).toBeLessThan(0.25);
  });

  it('estimate job equals the drawn estimate and reports bad input', async () => {
    const r = await estimateJob({ ...base, strategies: [base.strategies[1]], n: 300000 }, compileX);
    expect(r.estimate).toBeCloseTo(I, 12);
    await expect(
      estimateJob({ ...base, f: 'y + 1', strategies: [base.strategies[0]], n: 10 }, compileX),
    ).rejects.toThrow(/f:/);
  });
});

describe('samples field parsing', async () => {
  const { parseSamples } = await import('../../../src/scenes/monte-carlo/view/Fields');
  it('parses lists, empties and rejects garbage with a message', () => {
    expect(parseSamples('1.16, 1.98 ,0.54;1.26')).toEqual({ ok: true, value: [1.16, 1.98, 0.54, 1.26] });
    expect(parseSamples('  ')).toEqual({ ok: true, value: null });
    const bad = parseSamples('1, abc');
    expect(bad.ok).toBe(false);
    if (!bad.ok) expect(bad.message).toMatch(/abc/);
    expect(parseSamples(Array(40).fill(1).join(',')).ok).toBe(false);
  });
});

describe('formatCount', () => {
  it('writes what toLocaleString("en") writes, for counts of every length and the odd cases', () => {
    const xs = [
      0,
      1,
      9,
      10,
      99,
      100,
      999,
      1000,
      1001,
      9999,
      10000,
      12345,
      99999,
      100000,
      999999,
      1000000,
      1234567,
      10000000,
      2 ** 31,
      2 ** 32 + 7,
      Number.MAX_SAFE_INTEGER,
      -0,
      -1234,
      1.5,
      1234.5678,
      NaN,
      Infinity,
    ];
    for (let k = 0; k < 2000; k++) xs.push(Math.floor((k * 7919) ** 1.7) % 123456789);
    for (const x of xs) expect(formatCount(x), String(x)).toBe(x.toLocaleString('en'));
  });
});
