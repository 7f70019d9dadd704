/**
 * The words of the race's plots and of the "Explore further" plots: live numbers, the fitted slope
 * on log–log axes, "zero variance", and text that changes when a parameter changes. Expected
 * values come from the model's numbers and from direct recomputation, never from the app's text.
 */
import { describe, expect, it } from 'vitest';
import { unsuperscript } from '../../../src/ui/axis';
import { linearPdf1D, squarePdf1D } from '../../../src/core/sampling/pdf1d';
import { raceAt, racePoints, raceTrack } from '../../../src/scenes/monte-carlo/race';
import {
  crossings,
  describeErrors,
  describeEstimate,
  describeIntegrand,
  describeRace,
  plusMinus,
} from '../../../src/scenes/monte-carlo/view/describeRace';
import {
  describeEstimateHistogram,
  describeSeriesSet,
  seriesTable,
} from '../../../src/scenes/monte-carlo/view/plotWords';

const f = (x: number) => (x + 2) ** 2;
const I = 56 / 3;
const exam = (seed: number) => raceTrack(f, 0, 2, squarePdf1D(0, 2, 2), I, seed);

describe('the race in words', () => {
  const track = exam(1);
  const fr = raceAt(track, 4096, racePoints(track.max));

  it('|error|: the uniform lane’s fitted log–log slope near −½, the p ∝ f lane zero variance', () => {
    const d = describeErrors(fr.curve, fr.importance.zeroVariance);
    // one run's slope is noisy about −½: between −1 and −0.3, and the one the fit gives
    const m = /Uniform: .*falls as N([⁻⁰¹²³⁴⁵⁶⁷⁸⁹·]+) \(fitted slope (−\d\.\d\d)/.exec(d);
    expect(m, d).not.toBeNull();
    const slope = Number(m![2].replace('−', '-'));
    expect(slope).toBeGreaterThan(-1);
    expect(slope).toBeLessThan(-0.3);
    expect(Number(unsuperscript(m![1]).replace('·', '.'))).toBe(slope);
    expect(d).toContain('Importance: zero variance');
    // a ramp only approximates f: its error is summarized like the uniform one, with a slope
    const ramp = raceTrack(f, 0, 2, linearPdf1D(0, 2, 4, 16), I, 1);
    const rf = raceAt(ramp, 4096, racePoints(ramp.max));
    expect(rf.importance.zeroVariance).toBe(false);
    expect(describeErrors(rf.curve, false)).toMatch(/Importance: .*falls as N⁻/);
    expect(describeErrors({ n: [], u: [], uSe: [], uErr: [], i: [], iSe: [], iErr: [] }, true)).toContain(
      'no samples yet',
    );
  });

  it('a running estimate: its summary and where it is now against the exact I', () => {
    const d = describeEstimate('uniform', fr.curve.n, fr.curve.u, fr.uniform, I);
    expect(d).toContain('the uniform estimate');
    expect(d).toContain(`Now ${plusMinus(fr.uniform.estimate, fr.uniform.stderr)}`);
    expect(d).toContain('exact I = 18.6667');
    expect(describeEstimate('importance', fr.curve.n, fr.curve.i, fr.importance, I)).toContain(
      '(zero variance)',
    );
  });

  it('crossings of the exact value: between the points where estimate − I changes sign', () => {
    expect(crossings([0, 1, 2, 3], [1, 3, 1, 0], 2)).toEqual([0.5, 1.5]);
    expect(crossings([0, 1], [3, 3], 2)).toEqual([]);
    expect(crossings([0, 1, 2], [1, 2, 3], 2)).toEqual([1]);
    // every crossing lies between two N where the uniform estimate is on either side of I
    const xs = fr.curve.n.map(Math.log10);
    for (const x of crossings(xs, fr.curve.u, I)) {
      const k = xs.findIndex((v) => v >= x);
      expect(Math.sign(fr.curve.u[k] - I)).not.toBe(Math.sign(fr.curve.u[k - 1] - I) || 2);
    }
  });

  it('the integrand plot names the newest sample of each lane', () => {
    const d = describeIntegrand({
      a: 0,
      b: 2,
      fMin: 4,
      fMax: 16,
      importanceName: 'p ∝ f',
      uniform: fr.uniform,
      importance: fr.importance,
    });
    expect(d).toContain('from 4 to 16');
    expect(d).toContain(`Sample 4,096 dropped at x = ${Number(fr.uniform.x.toPrecision(4))}`);
    const none = raceAt(track, 0, []);
    expect(describeIntegrand({ a: 0, b: 2, fMin: 4, fMax: 16, importanceName: 'p ∝ f', ...none })).toContain(
      'No sample has dropped yet',
    );
  });

  it('changes with a parameter: another seed, another pdf', () => {
    const text = (tr: ReturnType<typeof exam>, name: string) => {
      const s = raceAt(tr, 1024, []);
      return describeRace({
        t: 1024,
        max: tr.max,
        uniform: s.uniform,
        importance: s.importance,
        importanceName: name,
        exact: I,
        half: null,
      });
    };
    const base = text(exam(1), 'p ∝ f');
    expect(text(exam(2), 'p ∝ f')).not.toBe(base);
    // held for ask=1: nothing of the result, not even the exact value
    const held = describeRace({
      t: 0,
      max: 8192,
      uniform: raceAt(exam(1), 0, []).uniform,
      importance: raceAt(exam(1), 0, []).importance,
      importanceName: 'p ∝ f',
      exact: I,
      half: null,
      held: true,
    });
    expect(held).toContain('once the results are revealed');
    expect(held).not.toContain('18.6');
    const ramp = text(raceTrack(f, 0, 2, linearPdf1D(0, 2, 4, 16), I, 1), 'the linear ramp');
    expect(ramp).toContain('importance (the linear ramp)');
    expect(ramp).not.toContain('zero variance');
  });
});

describe('the Explore plots in words and as tables', () => {
  it('one summary per series, with the slope on log–log axes', () => {
    const n = [1, 10, 100, 1000, 10000];
    const d = describeSeriesSet(
      [
        { label: 'uniform', xs: n, ys: n.map((v) => 3 / Math.sqrt(v)) },
        { label: 'stratified', xs: n, ys: n.map((v) => 3 / v ** 1.5) },
      ],
      { xLabel: 'N', yLabel: '|error|', logLog: true, empty: 'none' },
    );
    expect(d).toMatch(/^uniform: .*falls as N⁻⁰·⁵⁰.* stratified: .*falls as N⁻¹·⁵⁰/);
    expect(describeSeriesSet([], { xLabel: 'N', yLabel: 'y', empty: 'No run yet.' })).toBe('No run yet.');
  });

  it('a table of several series: the union of their x, a dash where one has no point', () => {
    const t = seriesTable('N', [
      { label: 'a', xs: [1, 10], ys: [5, 6] },
      { label: 'b', xs: [10, 100], ys: [7, 8] },
    ]);
    expect(t.columns).toEqual(['N', 'a', 'b']);
    expect(t.rows).toEqual([
      [1, 5, NaN],
      [10, 6, 7],
      [100, NaN, 8],
    ]);
  });

  it('the histogram of estimates: mean against exact in standard errors, the tallest bar', () => {
    const d = describeEstimateHistogram({
      count: 2000,
      N: 16,
      mean: 18.7,
      sd: 1.2,
      sem: 1.2 / Math.sqrt(2000),
      exact: I,
      centers: [17, 18, 19],
      counts: [10, 50, 20],
    });
    expect(d).toContain('2000 independent estimates, each from 16 samples');
    expect(d).toContain(`${((18.7 - I) / (1.2 / Math.sqrt(2000))).toPrecision(2)} standard errors off`);
    expect(d).toContain('the tallest bar, 50 estimates, is at 18');
    expect(
      describeEstimateHistogram({
        count: 0,
        N: 4,
        mean: NaN,
        sd: NaN,
        sem: NaN,
        exact: I,
        centers: [],
        counts: [],
      }),
    ).toContain('none yet');
  });
});
