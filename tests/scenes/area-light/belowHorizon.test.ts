/**
 * The part of the light below the shading point's horizon: the exact area of the unit square on
 * one side of a line, against a fine one-dimensional integration, its symmetries, and the
 * percentage the scene prints from it.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { defaultValues } from '../../../src/kit/params';
import { schema, type AreaLightParams } from '../../../src/scenes/area-light/params';
import { buildModel, percentOfPart, squareAreaBelow } from '../../../src/scenes/area-light/model';

/**
 * The same area by the midpoint rule along a, with the exact length of each column below the line
 * (clamped to [0, 1]): the integrand is continuous and piecewise linear for q ≠ 0, so N columns
 * leave an error far below 1e-6.
 */
function reference(p: number, q: number, c: number, N = 20000): number {
  let sum = 0;
  for (let k = 0; k < N; k++) {
    const a = (k + 0.5) / N;
    const r = c - a * p;
    const len = q > 0 ? r / q : q < 0 ? 1 - r / q : r > 0 ? 1 : 0;
    sum += Math.min(1, Math.max(0, len));
  }
  return sum / N;
}

const coef = fc.double({ min: -4, max: 4, noNaN: true });

describe('squareAreaBelow', () => {
  it('equals a fine integration of the columns below the line', () => {
    fc.assert(
      fc.property(
        coef,
        coef.filter((q) => Math.abs(q) > 1e-3),
        fc.double({ min: -5, max: 5, noNaN: true }),
        (p, q, c) => {
          expect(Math.abs(squareAreaBelow(p, q, c) - reference(p, q, c))).toBeLessThan(1e-6);
        },
      ),
      { seed: 36, numRuns: 200 },
    );
  });

  it('the two sides of the line make the whole square; more room below never lowers the area', () => {
    fc.assert(
      fc.property(
        coef,
        coef,
        fc.double({ min: -5, max: 5, noNaN: true }),
        fc.double({ min: 0, max: 3, noNaN: true }),
        (p, q, c, dc) => {
          const below = squareAreaBelow(p, q, c);
          expect(below).toBeGreaterThanOrEqual(0);
          expect(below).toBeLessThanOrEqual(1);
          expect(below + squareAreaBelow(-p, -q, -c)).toBeCloseTo(1, 12);
          expect(squareAreaBelow(p, q, c + dc)).toBeGreaterThanOrEqual(below - 1e-15);
        },
      ),
      { seed: 6, numRuns: 300 },
    );
  });

  it('known cuts: a diagonal, an edge, a corner, a flat line', () => {
    expect(squareAreaBelow(1, 1, 1)).toBeCloseTo(0.5, 15);
    expect(squareAreaBelow(0, 1, 0.3)).toBeCloseTo(0.3, 15);
    expect(squareAreaBelow(1, 1, 0.5)).toBeCloseTo(0.125, 15);
    expect(squareAreaBelow(0, 0, 1)).toBe(1);
    expect(squareAreaBelow(0, 0, 0)).toBe(0);
    expect(squareAreaBelow(2, 3, -1)).toBe(0);
    expect(squareAreaBelow(2, 3, 6)).toBe(1);
  });
});

describe('the scene’s notice of a light partly below the horizon', () => {
  const withP = (patch: Partial<AreaLightParams>): AreaLightParams => ({
    ...defaultValues(schema),
    ...patch,
  });

  it('prints the exact share: 31.8 % below reads 32 % (a 64 × 64 grid of the rectangle counted 31.25 %)', () => {
    // a vertical light (tilt −90°) of height 1 from z = −0.318 to 0.682 over a point at z = 0
    const m = buildModel(withP({ lc: [0, 1, 0.182], tilt: -90 }));
    expect(m.belowHorizon).toBeCloseTo(0.318, 12);
    expect(m.messages.some((x) => x.text.startsWith('32% of the light is below the horizon'))).toBe(true);
  });

  it('a sliver never reads 0 % and nearly all never 100 %', () => {
    expect(percentOfPart(0.001)).toBe('Less than 1%');
    expect(percentOfPart(0.004999)).toBe('Less than 1%');
    expect(percentOfPart(0.005)).toBe('1%');
    expect(percentOfPart(0.5)).toBe('50%');
    expect(percentOfPart(0.994)).toBe('99%');
    expect(percentOfPart(0.995)).toBe('Over 99%');
    expect(percentOfPart(0.99999)).toBe('Over 99%');
  });
});
