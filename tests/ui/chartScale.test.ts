/**
 * The shared chart guard (src/ui/chartScale): for every double, of data and of domain (NaN, ±∞,
 * subnormals, ±MAX_VALUE), a scale gives a finite coordinate and coordText never writes NaN or Infinity;
 * on ordinary domains the scales are the usual affine / log maps.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { COORD_LIMIT, clampExponent, coord, coordText, linearScale, logScale } from '../../src/ui/chartScale';

const anyDouble = fc.double(); // includes NaN, ±∞, ±0, subnormals, ±MAX_VALUE
const rangeEnd = fc.double({ min: -5000, max: 5000, noNaN: true });
const NUM = /^-?\d+(\.\d+)?$/;

describe('chartScale', () => {
  it('linearScale: a finite coordinate for any domain and any value (property)', () => {
    fc.assert(
      fc.property(anyDouble, anyDouble, rangeEnd, rangeEnd, anyDouble, (d0, d1, r0, r1, v) => {
        const y = linearScale(d0, d1, r0, r1)(v);
        expect(Number.isFinite(y)).toBe(true);
        expect(Math.abs(y)).toBeLessThanOrEqual(COORD_LIMIT);
        expect(coordText(y)).toMatch(NUM);
      }),
      { numRuns: 3000, seed: 6 },
    );
  });

  it('logScale: a finite coordinate for any domain and any value, subnormals included (property)', () => {
    fc.assert(
      fc.property(anyDouble, anyDouble, rangeEnd, rangeEnd, anyDouble, (d0, d1, r0, r1, v) => {
        const y = logScale(d0, d1, r0, r1)(v);
        expect(Number.isFinite(y)).toBe(true);
        expect(coordText(y)).toMatch(NUM);
      }),
      { numRuns: 3000, seed: 7 },
    );
  });

  it('coordText and coord never write NaN or Infinity (property)', () => {
    fc.assert(
      fc.property(anyDouble, anyDouble, fc.integer({ min: 0, max: 6 }), (v, fb, digits) => {
        expect(Number.isFinite(coord(v, fb))).toBe(true);
        expect(coordText(v, digits, fb)).toMatch(NUM);
      }),
      { numRuns: 3000, seed: 8 },
    );
  });

  it('is the ordinary map on ordinary domains, and monotone inside them (property)', () => {
    const s = linearScale(0, 2, 10, 110);
    expect(s(0)).toBe(10);
    expect(s(1)).toBe(60);
    expect(s(2)).toBe(110);
    const l = logScale(1, 1000, 0, 300);
    expect(l(10)).toBeCloseTo(100, 9);
    expect(l(1000)).toBeCloseTo(300, 9);
    fc.assert(
      fc.property(
        fc.double({ min: -1e300, max: 1e300, noNaN: true }),
        fc.double({ min: -1e300, max: 1e300, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (d0, d1, p, q) => {
          fc.pre(d1 > d0);
          const sc = linearScale(d0, d1, 0, 1000);
          const [a, b] = p < q ? [p, q] : [q, p];
          const va = d0 + a * (d1 - d0);
          const vb = d0 + b * (d1 - d0);
          fc.pre(Number.isFinite(va) && Number.isFinite(vb));
          expect(sc(va)).toBeLessThanOrEqual(sc(vb) + 1e-9);
        },
      ),
      { numRuns: 1000, seed: 9 },
    );
  });

  it('a subnormal data range (f = 1e-320·x) still spreads its decades over the axis', () => {
    const s = 2e-320;
    const e1 = clampExponent(Math.ceil(Math.log10(s)));
    const e0 = clampExponent(Math.floor(Math.log10(s)) - 5);
    expect(10 ** e0).toBeGreaterThan(0);
    const ly = logScale(10 ** e0, 10 ** e1, 200, 0);
    expect(ly(10 ** e0)).toBeCloseTo(200, 6);
    expect(ly(10 ** e1)).toBeCloseTo(0, 6);
    expect(ly(1e-321)).toBeGreaterThan(0);
    expect(ly(1e-321)).toBeLessThan(200);
  });
});
