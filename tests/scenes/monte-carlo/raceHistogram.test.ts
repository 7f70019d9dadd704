/**
 * The race's histograms (every sample drawn so far, binned), the zero-variance verdict, and the
 * descriptions built from them. Expected values come from direct recomputation, never from the app.
 */
import { describe, expect, it } from 'vitest';
import { squarePdf1D, uniformPdf1D, linearPdf1D, proportionalPdf1D } from '../../../src/core/sampling/pdf1d';
import { importanceEstimate, uniformEstimate } from '../../../src/core/estimators';
import {
  binRange,
  countIn,
  heavierHalf,
  RACE_BINS,
  raceBinIndex,
  raceCounts,
} from '../../../src/scenes/monte-carlo/raceHistogram';
import {
  estimateHasZeroVariance,
  ZERO_SPREAD_ULPS,
  zeroToRounding,
} from '../../../src/scenes/monte-carlo/zeroVariance';
import { raceAt, raceTrack } from '../../../src/scenes/monte-carlo/race';
import { schema } from '../../../src/scenes/monte-carlo/params';
import { parseParams } from '../../../src/kit/params';
import {
  describeHistogram,
  describeRace,
  laneText,
  plusMinus,
} from '../../../src/scenes/monte-carlo/view/describeRace';

const f = (x: number) => (x + 2) ** 2;
const I = (4 ** 3 - 2 ** 3) / 3;
const track = raceTrack(f, 0, 2, squarePdf1D(0, 2, 2), I, 1);

describe('race histograms: every sample drawn so far', () => {
  it('counts equal a direct binning of the first t samples, and sum to t', () => {
    for (const lane of [track.uniform, track.importance]) {
      const idx = raceBinIndex(lane.x, 0, 2);
      for (const t of [0, 1, 7, 1024, 5000, 8192]) {
        const c = raceCounts(idx, t);
        const want = new Array(RACE_BINS).fill(0);
        for (let i = 0; i < t; i++) want[Math.min(RACE_BINS - 1, Math.floor((lane.x[i] / 2) * RACE_BINS))]++;
        expect(Array.from(c)).toEqual(want);
        expect(c.reduce((s, v) => s + v, 0)).toBe(t);
      }
    }
  });

  it('bins: the last is closed at b, outside samples go to the end bins, ranges tile [a, b]', () => {
    expect(Array.from(raceBinIndex([0, 2, -1, 3, 0.999999], 0, 2, 4))).toEqual([0, 3, 0, 3, 1]);
    expect(binRange(0, 0, 2, 4)).toEqual([0, 0.5]);
    expect(binRange(3, 0, 2, 4)).toEqual([1.5, 2]);
    expect(countIn([0.2, 1, 1.5, 2], 4, 1, 2)).toBe(3);
    expect(countIn([0.2, 1, 1.5, 2], 2, 1, 2)).toBe(1);
  });

  it('importance samples crowd where f is large; uniform ones do not', () => {
    const half = heavierHalf(squarePdf1D(0, 2, 2), 0, 2);
    expect(half).toEqual([1, 2]);
    // the mass of p = 3(x + 2)²/56 on [1, 2] is (64 − 27)/56
    const imp = countIn(track.importance.x, 8192, 1, 2) / 8192;
    const uni = countIn(track.uniform.x, 8192, 1, 2) / 8192;
    expect(Math.abs(imp - 37 / 56)).toBeLessThan(0.02);
    expect(Math.abs(uni - 0.5)).toBeLessThan(0.02);
    // a ramp falling from a to b is heavier on the left
    expect(heavierHalf(linearPdf1D(0, 2, 3, 1), 0, 2)).toEqual([0, 1]);
    expect(heavierHalf(uniformPdf1D(0, 2), 0, 2)).toEqual([1, 2]);
  });
});

describe('zero variance, to rounding', () => {
  const eps = Number.EPSILON;

  it('is relative to the magnitude of the estimate and to machine epsilon', () => {
    expect(zeroToRounding(0, 0)).toBe(true);
    expect(zeroToRounding(0, 5)).toBe(true);
    expect(zeroToRounding(9.81e-17 * Math.sqrt(1024), 56 / 3)).toBe(true);
    expect(zeroToRounding(ZERO_SPREAD_ULPS * eps * 18, 18)).toBe(true);
    expect(zeroToRounding(2 * ZERO_SPREAD_ULPS * eps * 18, 18)).toBe(false);
    expect(zeroToRounding(1e-10, 1)).toBe(false);
    // the same spread is rounding noise next to a large estimate, not next to a small one
    expect(zeroToRounding(1e-12, 1e6)).toBe(true);
    expect(zeroToRounding(1e-12, 1e-3)).toBe(false);
    // scale-free: any power of two leaves the verdict alone
    for (const k of [-900, -300, 0, 300, 900]) {
      const s = 2 ** k;
      expect(zeroToRounding(3 * eps * s, s)).toBe(true);
      expect(zeroToRounding(1e-9 * s, s)).toBe(false);
    }
    expect(zeroToRounding(NaN, 1)).toBe(false);
    expect(zeroToRounding(1e-20, NaN)).toBe(false);
    expect(zeroToRounding(1e-20, 0)).toBe(false);
  });

  it('p ∝ f has it at every N of the race; uniform sampling and a tabulated p ∝ |f| do not', () => {
    for (const t of [2, 3, 100, 1024, 8192]) {
      const fr = raceAt(track, t, []);
      expect(fr.importance.zeroVariance, `t = ${t}`).toBe(true);
      expect(fr.uniform.zeroVariance, `t = ${t}`).toBe(false);
    }
    expect(raceAt(track, 1, []).importance.zeroVariance).toBe(false);
    expect(raceAt(track, 0, []).importance.zeroVariance).toBe(false);
    const g = (x: number) => Math.exp(x) + Math.sin(3 * x) + 2;
    const tab = proportionalPdf1D(g, 0, 2);
    if (!tab.ok) throw new Error('pdf');
    const tt = raceTrack(g, 0, 2, tab.pdf, 0, 1, 2000);
    expect(raceAt(tt, 2000, []).importance.zeroVariance).toBe(false);
  });

  it('estimates: the exam’s four samples with p ∝ f have zero variance, uniformly not', () => {
    const xs = [1.16, 1.98, 0.54, 1.26];
    const p = squarePdf1D(0, 2, 2);
    const fx = Float64Array.from(xs, f);
    expect(
      estimateHasZeroVariance(
        importanceEstimate(
          fx,
          Float64Array.from(xs, (x) => p.pdf(x)),
        ),
      ),
    ).toBe(true);
    expect(estimateHasZeroVariance(uniformEstimate(fx, 0, 2))).toBe(false);
    // one term: no spread to speak of
    expect(estimateHasZeroVariance({ n: 1, variance: 0, estimate: 3 })).toBe(false);
    // a constant f: every uniform term is the same, so zero variance too
    expect(estimateHasZeroVariance(uniformEstimate(Float64Array.from([3, 3, 3]), 0, 2))).toBe(true);
  });
});

describe('descriptions', () => {
  it('plusMinus writes the error to one digit (two from a leading 1) and the estimate to match', () => {
    expect(plusMinus(18.6234, 0.3123)).toBe('18.6 ± 0.3');
    expect(plusMinus(18.6234, 0.1312)).toBe('18.62 ± 0.13');
    expect(plusMinus(18.6234, 0.0042)).toBe('18.623 ± 0.004');
    expect(plusMinus(1234.5, 31)).toBe('1230 ± 30');
    expect(plusMinus(18.666666, 1e-17, true)).toBe('18.67 ± 0');
    expect(plusMinus(18.666, NaN)).toBe('18.67');
    expect(plusMinus(NaN, 1)).toBe('—');
    expect(plusMinus(1.23456e-9, 2.1e-11)).toBe('1.23×10⁻⁹ ± 2×10⁻¹¹');
    expect(plusMinus(1.23456e-9, 1.4e-11)).toBe('1.235×10⁻⁹ ± 1.4×10⁻¹¹');
  });

  it('the race: live numbers at t, "zero variance" for p ∝ f, and where the samples fell', () => {
    const at = (t: number) => {
      const fr = raceAt(track, t, []);
      return describeRace({
        t,
        max: track.max,
        uniform: fr.uniform,
        importance: fr.importance,
        importanceName: 'p ∝ f',
        exact: I,
        half: {
          lo: 1,
          hi: 2,
          uniform: countIn(track.uniform.x, t, 1, 2),
          importance: countIn(track.importance.x, t, 1, 2),
        },
      });
    };
    const fr = raceAt(track, 1024, []);
    const d = at(1024);
    expect(d.startsWith('1,024 samples: uniform estimate ')).toBe(true);
    expect(d).toContain(plusMinus(fr.uniform.estimate, fr.uniform.stderr));
    expect(d).toContain('importance (p ∝ f) 18.67 ± 0 (zero variance)');
    expect(d).toContain('exact I = 18.6667');
    const share = Math.round((100 * countIn(track.importance.x, 1024, 1, 2)) / 1024);
    expect(d).toContain(`${share} % of the importance samples lie in [1, 2]`);
    // it changes with t, and says so before the first sample
    expect(at(2000)).not.toBe(d);
    expect(at(0)).toContain('No samples drawn yet');
    expect(at(1)).toContain('1 sample: uniform estimate');
    expect(at(1)).toContain('no spread yet');
  });

  it('a lane without zero variance has no such words', () => {
    const fr = raceAt(track, 50, []);
    expect(laneText(fr.uniform)).not.toContain('zero variance');
    expect(laneText(fr.importance)).toContain('zero variance');
  });

  it('a histogram: fewest and most per bin, and the share in the heavier half', () => {
    const idx = raceBinIndex(track.importance.x, 0, 2);
    const c = raceCounts(idx, 1024);
    const d = describeHistogram({
      lane: 'importance',
      pdf: 'p(x) ∝ f(x)',
      counts: c,
      t: 1024,
      a: 0,
      b: 2,
      half: [1, 2],
      inHalf: countIn(track.importance.x, 1024, 1, 2),
    });
    expect(d).toContain('Histogram of all 1,024 importance samples in 24 bins over [0, 2]');
    expect(d).toContain(`most ${Math.max(...c)}`);
    expect(d).toContain(`fewest ${Math.min(...c)}`);
    // p grows with x: the most crowded bin is near b
    expect(c.indexOf(Math.max(...c))).toBeGreaterThan(RACE_BINS / 2);
    expect(
      describeHistogram({ lane: 'uniform', pdf: 'p', counts: c, t: 0, a: 0, b: 2, half: null, inHalf: 0 }),
    ).toContain('no samples yet');
  });

  it('the race opens at a position with samples, not at t = 0', () => {
    const t = parseParams(schema, '').values.t;
    expect(t).toBeGreaterThanOrEqual(256);
    expect(t).toBeLessThan(8192);
  });
});
