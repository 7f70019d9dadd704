import { describe, expect, it } from 'vitest';
import { summarizeSeries, superscriptExponent } from '../../src/ui/summary';
import { Rng } from '../../src/core/random/rng';

describe('summarizeSeries', () => {
  it('a rising series: trend, extremes with their x, the last value', () => {
    const xs = [0, 1, 2, 3, 4];
    const ys = xs.map((x) => x * x);
    const s = summarizeSeries(xs, ys, { xLabel: 't', yLabel: 'g' });
    expect(s).toMatch(/^g rises from 0 at t = 0 to 16 at t = 4/);
    expect(s).toContain('minimum 0 at t = 0');
    expect(s).toContain('maximum 16 at t = 4');
    expect(s).toContain('last value 16 at t = 4');
  });

  it('a dip: falls overall is not said when it ends where it starts; the minimum is inside', () => {
    const xs = [-2, -1, 0, 1, 2];
    const ys = xs.map((x) => x * x - 1);
    const s = summarizeSeries(xs, ys, { xLabel: 't', yLabel: 'g(t)' });
    expect(s).toContain('g(t) ends about where it starts');
    expect(s).toContain('minimum −1 at t = 0');
    expect(s).not.toContain('-1');
  });

  it('falls overall when not monotone, rises when monotone', () => {
    const s = summarizeSeries([1, 2, 3, 4], [10, 6, 7, 1], { xLabel: 'x', yLabel: 'y' });
    expect(s).toMatch(/^y falls overall/);
    expect(summarizeSeries([1, 2, 3], [1, 2, 2], { xLabel: 'x', yLabel: 'y' })).toMatch(/^y rises from/);
  });

  it('flat, one point, no data, non-finite points skipped', () => {
    expect(summarizeSeries([0, 1, 2], [3, 3, 3], { xLabel: 'x', yLabel: 'y' })).toMatch(
      /^y is flat at 3 from x = 0 to 2/,
    );
    expect(summarizeSeries([5], [2], { xLabel: 'x', yLabel: 'y' })).toBe(
      'y against x: one point, 2 at x = 5.',
    );
    expect(summarizeSeries([], [], { xLabel: 'x', yLabel: 'y' })).toBe('y against x: no data to show.');
    const s = summarizeSeries([0, 1, 2, 3], [1, NaN, Infinity, 4], { xLabel: 'x', yLabel: 'y' });
    expect(s).toContain('last value 4 at x = 3');
    expect(s).not.toMatch(/NaN|Infinity/);
  });

  it('logLog: the fitted slope of a Monte Carlo error curve, with real superscripts', () => {
    const g = new Rng(7);
    const r = () => g.nextFloat();
    const ns = [16, 64, 256, 1024, 4096, 16384];
    // |error| ≈ 2/√N times a seeded wobble of ±10 %
    const err = ns.map((n) => (2 / Math.sqrt(n)) * (0.9 + 0.2 * r()));
    const s = summarizeSeries(ns, err, { xLabel: 'N', yLabel: '|error|', logLog: true });
    const m = /falls as N([⁻⁰¹²³⁴⁵⁶⁷⁸⁹·]+) \(fitted slope (−\d\.\d\d)/.exec(s);
    expect(m, s).not.toBeNull();
    const slope = Number(m![2]!.replace('−', '-'));
    expect(slope).toBeGreaterThan(-0.6);
    expect(slope).toBeLessThan(-0.4);
    expect(m![1]).toBe(superscriptExponent(slope));
  });

  it('superscriptExponent writes −0.50 as ⁻⁰·⁵⁰ and 1 as ¹·⁰⁰', () => {
    expect(superscriptExponent(-0.5)).toBe('⁻⁰·⁵⁰');
    expect(superscriptExponent(1)).toBe('¹·⁰⁰');
  });

  it('uses the given format', () => {
    const s = summarizeSeries([0, 1], [0.123456, 0.5], {
      xLabel: 'u',
      yLabel: 'p',
      format: (v) => v.toFixed(1),
    });
    expect(s).toContain('0.1 at u = 0.0');
  });
});
