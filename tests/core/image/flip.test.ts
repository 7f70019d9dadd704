import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  csfFilters,
  DEFAULT_PPD,
  featureKernels,
  flipErrorMap,
  linearRgbToLab,
  maxColorDistance,
  redistribute,
  type RgbImage,
} from '../../../src/core/image/flip';

const solid = (w: number, h: number, rgb: readonly number[]): RgbImage => {
  const data = new Float64Array(3 * w * h);
  for (let i = 0; i < w * h; i++) data.set(rgb, 3 * i);
  return { width: w, height: h, data };
};

/**
 * The colour term by hand for two flat colours, from the paper's definitions with the textbook
 * sRGB matrix (IEC 61966-2-1) and Lab formulas, independent of the module's code: flat images have
 * no features, and every filter of a flat image returns it unchanged.
 */
function handFlatError(c1: readonly number[], c2: readonly number[]): number {
  const lin = (c: number) => (c > 0.04045 ? ((c + 0.055) / 1.055) ** 2.4 : c / 12.92);
  const lab = (c: readonly number[]) => {
    const [r, g, b] = c.map(lin);
    const X = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.9505;
    const Y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    const Z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.089;
    const f = (t: number) => (t > (6 / 29) ** 3 ? Math.cbrt(t) : t / (3 * (6 / 29) ** 2) + 4 / 29);
    return [116 * f(Y) - 16, 500 * (f(X) - f(Y)), 200 * (f(Y) - f(Z))];
  };
  const hyab = (p: number[], q: number[]) =>
    Math.abs(p[0] - q[0]) +
    Math.hypot((p[0] / 100) * p[1] - (q[0] / 100) * q[1], (p[0] / 100) * p[2] - (q[0] / 100) * q[2]);
  const cmax = hyab(lab([0, 1, 0]), lab([0, 0, 1])) ** 0.7;
  const e = hyab(lab(c1), lab(c2)) ** 0.7;
  return e < 0.4 * cmax ? (0.95 / (0.4 * cmax)) * e : 0.95 + ((e - 0.4 * cmax) / (cmax - 0.4 * cmax)) * 0.05;
}

describe('LDR-FLIP', () => {
  it('identical images give 0 everywhere', () => {
    const img = {
      width: 9,
      height: 7,
      data: Float64Array.from({ length: 189 }, (_, i) => ((i * 37) % 101) / 100),
    };
    expect(Array.from(flipErrorMap(img, img)).every((v) => v === 0)).toBe(true);
  });

  it('flat colours give the colour term derived by hand from the paper', () => {
    const pairs: [number[], number[]][] = [
      [
        [0, 0, 0],
        [1, 1, 1],
      ],
      [
        [0.2, 0.4, 0.6],
        [0.25, 0.4, 0.6],
      ],
      [
        [1, 0, 0],
        [0, 0, 1],
      ],
      [
        [0.5, 0.5, 0.5],
        [0.52, 0.5, 0.5],
      ],
    ];
    for (const [a, b] of pairs) {
      const m = flipErrorMap(solid(5, 4, a), solid(5, 4, b));
      const want = handFlatError(a, b);
      for (const v of m) expect(Math.abs(v - want)).toBeLessThan(2e-4);
    }
  });

  it('black against white is the largest error between any two greys', () => {
    const bw = flipErrorMap(solid(3, 3, [0, 0, 0]), solid(3, 3, [1, 1, 1]))[4];
    expect(bw).toBeGreaterThan(0.95);
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (a, b) => {
          const e = flipErrorMap(solid(3, 3, [a, a, a]), solid(3, 3, [b, b, b]))[4];
          expect(e).toBeLessThanOrEqual(bw + 1e-9);
        },
      ),
      { seed: 3, numRuns: 40 },
    );
  });

  it('is symmetric in its two images and stays in [0, 1]', () => {
    fc.assert(
      fc.property(fc.integer({ min: 1, max: 2 ** 31 }), (seed) => {
        let s = seed;
        const rnd = () => (s = (Math.imul(s, 1103515245) + 12345) >>> 0) / 2 ** 32;
        const a = { width: 12, height: 10, data: Float64Array.from({ length: 360 }, rnd) };
        const b = { width: 12, height: 10, data: Float64Array.from({ length: 360 }, rnd) };
        const ab = flipErrorMap(a, b);
        const ba = flipErrorMap(b, a);
        for (let i = 0; i < ab.length; i++) {
          expect(Math.abs(ab[i] - ba[i])).toBeLessThan(1e-12);
          expect(ab[i]).toBeGreaterThanOrEqual(0);
          expect(ab[i]).toBeLessThanOrEqual(1);
        }
      }),
      { seed: 5, numRuns: 10 },
    );
  });

  it('an edge that moves is an error where it moved, nowhere far from it', () => {
    const w = 40;
    const edge = (at: number) => {
      const d = new Float64Array(3 * w * 8);
      for (let y = 0; y < 8; y++)
        for (let x = 0; x < w; x++) d.fill(x < at ? 0.1 : 0.9, 3 * (y * w + x), 3 * (y * w + x) + 3);
      return { width: w, height: 8, data: d };
    };
    const m = flipErrorMap(edge(20), edge(21));
    expect(m[4 * w + 20]).toBeGreaterThan(0.5);
    expect(m[4 * w + 2]).toBe(0);
    expect(m[4 * w + 38]).toBe(0);
  });

  it('a larger viewing distance (more pixels per degree) blurs more: a one-pixel dot matters less', () => {
    const dot = (v: number) => {
      const d = new Float64Array(3 * 15 * 15).fill(0.5);
      d.fill(v, 3 * (7 * 15 + 7), 3 * (7 * 15 + 7) + 3);
      return { width: 15, height: 15, data: d };
    };
    const near = flipErrorMap(dot(0.5), dot(1), 10)[7 * 15 + 7];
    const far = flipErrorMap(dot(0.5), dot(1), 200)[7 * 15 + 7];
    expect(near).toBeGreaterThan(far);
  });

  it('the filters are normalized and sized by the pixels per degree', () => {
    for (const ppd of [10, DEFAULT_PPD, 150]) {
      for (const f of csfFilters(ppd)) {
        const total = f.terms.reduce((s, t) => s + t.weight * t.taps.reduce((a, b) => a + b, 0) ** 2, 0);
        expect(total).toBeCloseTo(1, 12);
        expect(f.terms[0].taps.length).toBe(
          2 * Math.ceil(3 * Math.sqrt(0.04 / (2 * Math.PI ** 2)) * ppd) + 1,
        );
      }
      const k = featureKernels(ppd);
      const pos = (a: Float64Array) => a.filter((v) => v > 0).reduce((s, v) => s + v, 0);
      const neg = (a: Float64Array) => a.filter((v) => v < 0).reduce((s, v) => s + v, 0);
      expect(pos(k.edge)).toBeCloseTo(1, 12);
      expect(neg(k.edge)).toBeCloseTo(-1, 12);
      expect(pos(k.point)).toBeCloseTo(1, 12);
      expect(neg(k.point)).toBeCloseTo(-1, 12);
      expect(k.gauss.length).toBe(2 * Math.ceil(3 * 0.5 * 0.082 * ppd) + 1);
    }
    expect(DEFAULT_PPD).toBeCloseTo(67.0206, 4);
  });

  it('redistributes the colour error onto [0, 1] with the knee at p_c · cmax → p_t', () => {
    const cmax = maxColorDistance();
    expect(redistribute(0, cmax)).toBe(0);
    expect(redistribute(0.4 * cmax, cmax)).toBeCloseTo(0.95, 12);
    expect(redistribute(cmax, cmax)).toBeCloseTo(1, 12);
    const lab = [0, 0, 0];
    linearRgbToLab(1, 1, 1, lab);
    expect(lab[0]).toBeCloseTo(100, 6);
    expect(Math.abs(lab[1]) + Math.abs(lab[2])).toBeLessThan(1e-3);
  });

  it('names what is wrong with its input', () => {
    expect(() => flipErrorMap(solid(2, 2, [0, 0, 0]), solid(3, 2, [0, 0, 0]))).toThrow(/2×2 against 3×2/);
    expect(() => flipErrorMap(solid(2, 2, [0, 0, 0]), solid(2, 2, [0, 0, 0]), -1)).toThrow(
      /pixels per degree/,
    );
  });
});
