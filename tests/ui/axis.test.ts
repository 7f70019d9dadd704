/** The SVG plots' axis helpers (src/ui/axis.ts): tick steps, ticks, labels, superscripts. */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { niceStep, niceTicks, pow10Text, superscript, tickLabel, unsuperscript } from '../../src/ui/axis';

describe('niceStep', () => {
  it("'round' picks the nearest of 1, 2, 5, 10 × 10ⁿ; 'atLeast' the smallest of 1, 2, 2.5, 5, 10 not below the raw step", () => {
    expect(niceStep(0, 1.2, 1)).toBeCloseTo(1, 12); // raw 1.2 → 1
    expect(niceStep(0, 2.4, 1)).toBeCloseTo(2, 12); // raw 2.4 → 2
    expect(niceStep(0, 40, 10)).toBeCloseTo(5, 12); // raw 4 → 5
    expect(niceStep(0, 0.08, 1)).toBeCloseTo(0.1, 12); // raw 0.08 → 0.1
    expect(niceStep(0, 1.2, 1, 'atLeast')).toBeCloseTo(2, 12);
    expect(niceStep(0, 2.2, 1, 'atLeast')).toBeCloseTo(2.5, 12);
    expect(niceStep(0, 0.3, 1, 'atLeast')).toBeCloseTo(0.5, 12);
  });
});

describe('niceTicks', () => {
  it('lists the multiples of the step inside the range, without rounding noise', () => {
    expect(niceTicks(0, 1, 10)).toEqual({
      ticks: [0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1],
      step: expect.closeTo(0.1, 12),
    });
    expect(niceTicks(-0.37, 0.52, 4, 'atLeast').ticks).toEqual([-0.25, 0, 0.25, 0.5]);
    expect(niceTicks(3, 3).ticks).toEqual([3]);
    expect(niceTicks(0, Number.POSITIVE_INFINITY)).toEqual({ ticks: [0], step: 1 });
    expect(niceTicks(Number.NaN, 1).ticks.length).toBe(1);
  });

  it('every tick lies in the range, ticks are one step apart, and there are about `count` of them', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -1e6, max: 1e6, noNaN: true }),
        fc.double({ min: 1e-6, max: 1e6, noNaN: true }),
        fc.integer({ min: 1, max: 12 }),
        fc.constantFrom<'round' | 'atLeast'>('round', 'atLeast'),
        (lo, span, count, ladder) => {
          const hi = lo + span;
          if (!(hi > lo)) return true;
          const { ticks, step } = niceTicks(lo, hi, count, ladder);
          // ticks are rounded to 12 significant digits
          const eps = step * 1e-6 + Math.max(Math.abs(lo), Math.abs(hi)) * 1e-11;
          if (ticks.some((t) => t < lo - eps || t > hi + eps)) return false;
          for (let i = 1; i < ticks.length; i++)
            if (Math.abs(ticks[i]! - ticks[i - 1]! - step) > eps) return false;
          return ticks.length >= Math.floor(count / 2.5) && ticks.length <= 2 * count + 2;
        },
      ),
      { seed: 22, numRuns: 500 },
    );
  });
});

describe('tickLabel', () => {
  it('writes decimals the step needs, a real minus sign, and m×10ⁿ for large values or tiny steps', () => {
    expect(tickLabel(0.5, 0.1)).toBe('0.5');
    expect(tickLabel(-0.25, 0.05)).toBe('−0.25');
    expect(tickLabel(3, 1)).toBe('3');
    expect(tickLabel(1e-12, 0.1)).toBe('0');
    expect(tickLabel(200000, 100000)).toBe('2×10⁵');
    expect(tickLabel(1e6, 1e5)).toBe('10⁶');
    expect(tickLabel(-1e6, 1e5)).toBe('−10⁶');
    expect(tickLabel(0.0002, 0.0001)).toBe('2×10⁻⁴');
    // a quarter step keeps both decimals; a narrow range far from 0 keeps the digits down to its step
    expect(tickLabel(0.25, 0.25)).toBe('0.25');
    expect(tickLabel(-1.001e-7, 1e-10)).toBe('−1.001×10⁻⁷');
  });

  it('neighbouring ticks never read the same, however narrow the range is against its values', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -1e9, max: 1e9, noNaN: true }),
        fc.double({ min: 1e-9, max: 1e9, noNaN: true }),
        fc.integer({ min: 2, max: 10 }),
        fc.constantFrom<'round' | 'atLeast'>('round', 'atLeast'),
        (lo, span, count, ladder) => {
          const hi = lo + span;
          // (niceTicks rounds ticks to 12 significant digits: narrower ranges are out of its scope)
          if (!(hi > lo) || span < Math.max(Math.abs(lo), Math.abs(hi)) * 1e-9) return;
          const { ticks, step } = niceTicks(lo, hi, count, ladder);
          const labels = ticks.map((t) => tickLabel(t, step));
          expect(new Set(labels).size, labels.join(' | ')).toBe(labels.length);
        },
      ),
      { seed: 20261207, numRuns: 500 },
    );
  });
});

describe('superscripts', () => {
  it('raises what has a superscript, keeps the rest, and reads digits and signs back', () => {
    expect(superscript('-12')).toBe('⁻¹²');
    expect(superscript('n+1')).toBe('ⁿ⁺¹');
    expect(superscript('x')).toBe('x');
    expect(pow10Text(-3)).toBe('10⁻³');
    expect(pow10Text(0)).toBe('10⁰');
    expect(unsuperscript('⁻¹²')).toBe('-12');
    expect(unsuperscript('×10⁸')).toBe('×108');
    fc.assert(
      fc.property(
        fc.integer({ min: -400, max: 400 }),
        (e) => unsuperscript(superscript(String(e))) === String(e),
      ),
    );
  });
});
