// What a screen reader hears of the ray–sphere figures: the case with its live numbers, changing
// when r, the origin or the direction change; the handles' value texts; the plot summaries.
import { describe, expect, it } from 'vitest';
import {
  caseShort,
  digitsApart,
  deltaEvents,
  describeDeltaPlot,
  describeGPlot,
  describeRaySphere,
  gEvents,
  gSamples,
  handleText,
  num,
  sweepPlaceText,
} from '../../../src/scenes/ray-sphere/view/describe';
import { checkInputs } from '../../../src/scenes/ray-sphere/inputs';
import { computeModel } from '../../../src/scenes/ray-sphere/model';
import { makeSweep, sweepAt } from '../../../src/scenes/ray-sphere/sweep';
import { sweepSeries } from '../../../src/scenes/ray-sphere/sweepSeries';
import { formatNumber } from '../../../src/ui/Readout';

type V = [number, number, number];
const model = (o: V, d: V, c: V, r: number, method: 'stable' | 'naive' = 'stable') =>
  computeModel({ o, d, c, r, method });
const say = (o: V, d: V, c: V, r: number) => describeRaySphere(model(o, d, c, r), { method: 'stable' });

describe('describeRaySphere', () => {
  it('a miss: Δ, no root, the closest approach beyond the radius', () => {
    const m = model([-3, 1.2, 0], [1, 0, 0], [0, 0, 0], 1);
    const s = describeRaySphere(m, { method: 'stable' });
    expect(s).toMatch(/^The ray misses: Δ = −/);
    expect(s).toContain(`Δ = ${num(m.chosen!.discriminant)} < 0`);
    expect(s).toContain('passes 1.2 from C, 0.2 beyond the radius');
  });
  it('two hits: both roots as the readouts round them, and the hit point o + t₀ d', () => {
    const m = model([-3, 0.3, 0.2], [1, 0, 0], [0, 0, 0], 1);
    const s = describeRaySphere(m, { method: 'stable' });
    const res = m.chosen!;
    expect(s).toContain(`t₀ = ${formatNumber(res.t0!, 4)}`);
    expect(s).toContain(`t₁ = ${formatNumber(res.t1!, 4)}`);
    expect(s).toContain(`hit point p = (${num(-3 + res.t0!)}, 0.3, 0.2)`);
    expect(s).toContain('inside the radius');
  });
  it('tangent, inside and behind say what the exam asks about them', () => {
    expect(say([-5, 1, 0], [1, 0, 0], [0, 0, 0], 1)).toMatch(/tangent: Δ = 0, one double root t₀ = t₁ = 5/);
    expect(say([-5, 1, 0], [1, 0, 0], [0, 0, 0], 1)).toContain('exactly at the radius');
    const inside = say([0.2, -0.3, 0.1], [1, 0.5, 0], [0, 0, 0], 1);
    expect(inside).toMatch(/origin is inside.*t₀ = −[\d.]+ lies behind.*exit t₁ = [\d.]+/);
    expect(say([3, 0.3, 0.2], [1, 0, 0], [0, 0, 0], 1)).toMatch(/behind the origin.*no hit/);
  });
  it('changes when r, the origin or the direction change', () => {
    const base = say([-3, 0.3, 0.2], [1, 0, 0], [0, 0, 0], 1);
    expect(say([-3, 0.3, 0.2], [1, 0, 0], [0, 0, 0], 1.5)).not.toBe(base);
    expect(say([-3, 0.5, 0.2], [1, 0, 0], [0, 0, 0], 1)).not.toBe(base);
    expect(say([-3, 0.3, 0.2], [1, 0.1, 0], [0, 0, 0], 1)).not.toBe(base);
    expect(say([-3, 0.3, 0.2], [1, 0, 0], [0, 0, 0], 1.5)).toContain('r = 1.5');
  });
  it('names the method, the arithmetic, the sweep position τ and a figure not to scale', () => {
    const far = computeModel({ o: [0, 0, 0], d: [1, 5e-9, 0], c: [1e8, 0, 0], r: 1, method: 'naive' });
    const s = describeRaySphere(far, { method: 'naive', sweep: { mode: 'offset', tau: 0.25, x: -0.5 } });
    expect(s).toContain('Textbook Δ, double arithmetic.');
    expect(s).toContain('Not to scale: the origin is 1×10⁸ radii from the centre.');
    expect(s).toContain('Sweep τ = 0.250, h / r = −0.500.');
    const f32 = computeModel({
      o: [-3, 0.3, 0.2],
      d: [1, 0, 0],
      c: [0, 0, 0],
      r: 1,
      method: 'stable',
      precision: 'f32',
    });
    expect(describeRaySphere(f32, { method: 'stable' })).toContain('float32 arithmetic');
  });
});

describe('handle value texts', () => {
  const m = model([-3, 0.3, 0.2], [1, 0, 0], [0, 0, 0], 1);
  const ray = { ...m.input, res: m.chosen, distanceRatio: m.distanceRatio };
  it('say where each handle is and what the ray does', () => {
    expect(handleText('o', ray, [1, 0]).valueText).toBe(`o = (−3, 0.3, 0.2); ${caseShort(m.chosen)}`);
    expect(handleText('c', ray, [1, 0]).valueText).toMatch(/^C = \(0, 0, 0\); the ray hits at t₀ = /);
    expect(handleText('r', ray, [1, 0])).toMatchObject({ valueNow: 1, min: 0 });
    expect(handleText('tip', ray, [0, 1])).toMatchObject({ valueNow: 90 });
  });
  it('the consequence follows the case', () => {
    const miss = model([-3, 2, 0], [1, 0, 0], [0, 0, 0], 1).chosen;
    expect(caseShort(miss)).toMatch(/^the ray misses \(Δ = −/);
    expect(caseShort(model([3, 0.3, 0.2], [1, 0, 0], [0, 0, 0], 1).chosen)).toMatch(/behind/);
  });
});

describe('the plots in words, as data and as events', () => {
  const sw = makeSweep(checkInputs({ o: [-3, 0.3, 0.2], d: [1, 0, 0], c: [0, 0, 0], r: 1 }), 'offset', 2.5);
  const series = sweepSeries({ method: 'stable' }, sw);
  const tangentX = series.tangents.map((t) => sweepAt(sw, t).x);
  it('g(t): vertex, roots and which is the hit; samples and events at the roots', () => {
    const res = model([-3, 0.3, 0.2], [1, 0, 0], [0, 0, 0], 1).chosen!;
    const s = describeGPlot(res, series.gWindow);
    expect(s).toContain(`lowest at t = 3 where g = ${num(-res.discriminant / (4 * res.a))}`);
    expect(s).toContain(`crosses zero at t₀ = ${num(res.t0!)} and t₁ = ${num(res.t1!)}: t₀ is the hit`);
    const { t, g } = gSamples(res, series.gWindow, 40);
    expect(t).toHaveLength(41);
    // g changes sign exactly across the roots
    for (let i = 0; i < t.length; i++) expect(g[i] < 0).toBe(t[i] > res.t0! && t[i] < res.t1!);
    expect(gEvents(res).map((e) => e.kind)).toEqual(['root', 'root']);
    const miss = model([-3, 2, 0], [1, 0, 0], [0, 0, 0], 1).chosen!;
    expect(describeGPlot(miss, series.gWindow)).toMatch(/above zero everywhere: no root, a miss/);
    expect(gEvents(miss)).toEqual([]);
    const tan = model([-5, 1, 0], [1, 0, 0], [0, 0, 0], 1).chosen!;
    expect(gEvents(tan).map((e) => e.kind)).toEqual(['tangent']);
  });
  it('Δ against the sweep: crossings at ±1 (tangent), the cases in order, where it is now', () => {
    const s = describeDeltaPlot(series, tangentX, 'offset', { x: 0.3, disc: 3.64 });
    expect(s).toMatch(/crosses zero at h \/ r = −1 and 1 \(tangent\)/);
    expect(s).toContain('Cases along the sweep: miss up to h / r ≈ ');
    expect(s).toContain(', then two hits up to');
    expect(s).toContain('Now at h / r = 0.3: Δ = 3.64.');
    expect(deltaEvents(tangentX, 'offset').map((e) => e.kind)).toEqual(['tangent', 'tangent']);
  });
  it('the far preset: the textbook Δ has the wrong sign, and the summary says so', () => {
    const far = makeSweep(
      checkInputs({ o: [0, 0, 0], d: [1, 5e-9, 0], c: [1e8, 0, 0], r: 1 }),
      'offset',
      2.5,
    );
    const fs = sweepSeries({ method: 'stable' }, far);
    const s = describeDeltaPlot(
      fs,
      fs.tangents.map((t) => sweepAt(far, t).x),
      'offset',
      { x: 0, disc: null },
    );
    expect(s).toMatch(/textbook Δ has the wrong sign \(or is 0\) at \d+ of \d+ positions/);
  });
  it('the sweep position is τ, and the transport text matches', () => {
    expect(sweepPlaceText({ mode: 'rotate', tau: 0.5, x: 0.25 })).toBe('τ = 0.500, ψ / α = 0.250');
  });
});

describe('numbers close together', () => {
  it('roots 2·10⁻⁵ apart at 10⁵ are told apart (the grazing preset)', () => {
    const s = say([-1e5, 0.99999, 0], [1, 0, 0], [0, 0, 0], 1);
    const [, a, b] = /t₀ = ([^ ]+) and t₁ = ([^ ,]+)/.exec(s)!;
    expect(a).not.toBe(b);
    expect(digitsApart(99999.99, 100000.01)).toBe(9);
    expect(digitsApart(2, 4)).toBe(4);
  });
});
