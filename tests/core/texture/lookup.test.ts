import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { create, all } from 'mathjs';
import {
  EXAM_LOOKUP,
  WRAP_MODES,
  bilinear,
  bilinearStencil,
  bilinearSteps,
  examGrid,
  makeGrid,
  nearest,
  nearestStencil,
  nearestValueFast,
  randomGrid,
  sphericalUV,
  texel,
  type LookupOptions,
  type TextureGrid,
} from '../../../src/core/texture';

/**
 * The exam's grid as a function of the node coordinates: value(i, j) = 21 − 5j + i with
 * u = i/4, v = j/4 is L(u, v) = 21 − 20 v + 4 u. Bilinear interpolation reproduces linear
 * functions exactly, so L is the closed-form reference for every corner-aligned lookup on it.
 */
const L = (u: number, v: number) => 21 - 20 * v + 4 * u;
const exam = examGrid();
const OPTS: LookupOptions[] = [];
for (const align of ['corner', 'center'] as const)
  for (const vflip of [false, true]) for (const wrap of WRAP_MODES) OPTS.push({ align, vflip, wrap });

describe('the exam, Q3 (values derived from the grid definition, not copied from the key)', () => {
  it('(a) nearest of (0.4, 0.24) is the node (0.5, 0.25) = value(2, 1)', () => {
    const s = nearestStencil(exam, 0.4, 0.24, EXAM_LOOKUP);
    expect([s.i, s.j]).toEqual([Math.round(0.4 * 4), Math.round(0.24 * 4)]);
    expect([s.nodeU, s.nodeV]).toEqual([0.5, 0.25]);
    expect(s.value).toBe(21 - 5 * 1 + 2);
    expect(s.value).toBe(18);
  });

  it("(b) bilinear of (0.4, 0.24) equals L(0.4, 0.24) = 17.8, and so do the key's steps c_u, c_l, c", () => {
    const s = bilinearStencil(exam, 0.4, 0.24, EXAM_LOOKUP);
    expect(s.value).toBeCloseTo(L(0.4, 0.24), 13);
    expect(L(0.4, 0.24)).toBeCloseTo(17.8, 13);
    expect([s.i0, s.i1, s.j0, s.j1]).toEqual([1, 2, 0, 1]);
    expect([s.u0, s.u1, s.v0, s.v1]).toEqual([0.25, 0.5, 0, 0.25]);
    expect(s.du).toBe(0.25);
    expect([s.t00, s.t10, s.t01, s.t11]).toEqual([22, 23, 17, 18]);
    const st = bilinearSteps(s);
    expect(st.cu).toBeCloseTo(L(0.4, 0.25), 13); // upper row, v = 0.25
    expect(st.cl).toBeCloseTo(L(0.4, 0), 13); // lower row, v = 0
    expect(st.c).toBeCloseTo(L(0.4, 0.24), 13);
    expect(st.c).toBeCloseTo(s.value, 13);
    expect(bilinear(exam, 0.4, 0.24, EXAM_LOOKUP)).toBe(s.value);
  });

  it('(c) sphere point with y/x = 1, z/r = √2/2 → (0.125, 0.25) → bilinear L(1/8, 1/4) = 16.5', () => {
    const p = sphericalUV(1, 1, Math.SQRT2);
    expect(p.ok).toBe(true);
    if (!p.ok) return;
    expect(p.u).toBeCloseTo(0.125, 15);
    expect(p.v).toBeCloseTo(0.25, 15);
    const b = bilinear(exam, p.u, p.v, EXAM_LOOKUP);
    expect(b).toBeCloseTo(L(0.125, 0.25), 12);
    expect(b).toBeCloseTo(16.5, 12);
  });

  it("(c) without normalization, (π/4, π/4) gives 21 − 4π ≈ 8.4336, not the key's 8.44", () => {
    const p = sphericalUV(1, 1, Math.SQRT2);
    if (!p.ok) throw new Error('unreachable');
    expect(p.phi).toBeCloseTo(Math.PI / 4, 15);
    expect(p.theta).toBeCloseTo(Math.PI / 4, 15);
    // π/4 ≈ 0.785 lies inside [0, 1], so clamp addressing does not touch it
    const b = bilinear(exam, p.phi, p.theta, EXAM_LOOKUP);
    const M = create(all, { number: 'BigNumber', precision: 40 });
    const ref = Number(M.evaluate('21 - 4 * pi'));
    expect(b).toBeCloseTo(ref, 12);
    expect(L(Math.PI / 4, Math.PI / 4)).toBeCloseTo(ref, 12);
    expect(Math.abs(b - 8.44)).toBeGreaterThan(0.006); // the key's printed figure is off in the 2nd decimal
    expect(b.toFixed(2)).toBe('8.43');
  });

  it("the key's alternative reading v' = 1 − v: nearest (0.5, 0.75) = value(2, 3), bilinear L(0.4, 0.76)", () => {
    const o = { ...EXAM_LOOKUP, vflip: true };
    expect(nearest(exam, 0.4, 0.24, o)).toBe(21 - 5 * 3 + 2);
    expect(bilinear(exam, 0.4, 0.24, o)).toBeCloseTo(L(0.4, 0.76), 13);
  });

  it('GPU texel centres on the exam grid: s = uN − ½, so bilinear is 21 − 5t + s at s = 1.5, t = 0.7', () => {
    const o: LookupOptions = { align: 'center', vflip: false, wrap: 'clamp' };
    const s = 0.4 * 5 - 0.5;
    const t = 0.24 * 5 - 0.5;
    expect(bilinear(exam, 0.4, 0.24, o)).toBeCloseTo(21 - 5 * t + s, 13);
    // nearest: the texel whose cell [i/5, (i+1)/5) holds the query: i = ⌊2⌋ = 2, j = ⌊1.2⌋ = 1
    expect(nearest(exam, 0.4, 0.24, o)).toBe(21 - 5 * 1 + 2);
    const st = bilinearStencil(exam, 0.4, 0.24, o);
    expect(st.du).toBe(0.2);
    expect(st.u0).toBeCloseTo(0.3, 15);
    expect(st.u1).toBeCloseTo(0.5, 15);
    expect(bilinearSteps(st).c).toBeCloseTo(st.value, 12);
  });
});

describe('edges: u, v exactly 0 and 1, and outside [0, 1]', () => {
  it('corner nodes: the four corners return the corner values exactly in every wrap mode', () => {
    for (const wrap of WRAP_MODES) {
      const o: LookupOptions = { align: 'corner', vflip: false, wrap };
      for (const [u, v, i, j] of [
        [0, 0, 0, 0],
        [1, 0, 4, 0],
        [0, 1, 0, 4],
        [1, 1, 4, 4],
      ]) {
        expect(bilinear(exam, u, v, o)).toBe(texel(exam, i, j));
        expect(nearest(exam, u, v, o)).toBe(texel(exam, i, j));
      }
      const s = bilinearStencil(exam, 1, 1, o);
      expect([s.i0, s.i1, s.fu, s.fv]).toEqual([3, 4, 1, 1]); // the last cell, not one past it
    }
  });

  it('corner nodes outside [0, 1]: clamp sticks to the edge, repeat wraps, mirror reflects', () => {
    const c = (wrap: LookupOptions['wrap']) => ({ align: 'corner', vflip: false, wrap }) as LookupOptions;
    expect(bilinear(exam, -0.3, 1.7, c('clamp'))).toBeCloseTo(L(0, 1), 13);
    expect(bilinear(exam, 1.4, -0.76, c('repeat'))).toBeCloseTo(L(0.4, 0.24), 12);
    expect(bilinear(exam, 1.4, -0.24, c('mirror'))).toBeCloseTo(L(0.6, 0.24), 12);
    expect(bilinear(exam, -0.4, 2.24, c('mirror'))).toBeCloseTo(L(0.4, 0.24), 12);
    expect(nearest(exam, 2, 2, c('repeat'))).toBe(texel(exam, 0, 0));
  });

  it('texel centres: clamp holds the edge texel within half a texel of the border; repeat mixes across it', () => {
    const g = makeGrid(2, 2, (i, j) => [1, 2, 3, 4][j * 2 + i]);
    const cl: LookupOptions = { align: 'center', vflip: false, wrap: 'clamp' };
    const rp: LookupOptions = { align: 'center', vflip: false, wrap: 'repeat' };
    const mi: LookupOptions = { align: 'center', vflip: false, wrap: 'mirror' };
    expect(bilinear(g, 0, 0, cl)).toBe(1);
    expect(bilinear(g, 0.25, 0.25, cl)).toBe(1); // exactly on the centre of texel (0, 0)
    expect(bilinear(g, 1, 1, cl)).toBe(4);
    // u = 0 under repeat: taps are the last and the first column, half each
    const s = bilinearStencil(g, 0, 0.25, rp);
    expect([s.i0, s.i1, s.fu]).toEqual([1, 0, 0.5]);
    expect(s.value).toBe((1 + 2) / 2);
    expect(bilinear(g, 1, 0.25, rp)).toBe(bilinear(g, 0, 0.25, rp)); // period 1
    expect(bilinear(g, 0, 0.25, mi)).toBe(1); // mirrored: the edge texel meets itself
    // nearest at u = 1: clamp → last texel; repeat → ⌊N⌋ = N wraps to texel 0 (as a GPU does)
    expect(nearest(g, 1, 0.25, cl)).toBe(2);
    expect(nearest(g, 1, 0.25, rp)).toBe(1);
    expect(nearest(g, 1, 0.25, mi)).toBe(2);
    expect(nearest(g, -0.01, 0.25, rp)).toBe(2);
  });

  it('v-flip maps v = 0 to the top row and v = 1 to the bottom row', () => {
    const o = { ...EXAM_LOOKUP, vflip: true };
    expect(nearest(exam, 0, 0, o)).toBe(texel(exam, 0, 4));
    expect(nearest(exam, 0, 1, o)).toBe(texel(exam, 0, 0));
  });

  it('non-finite queries fall back to 0 instead of NaN', () => {
    for (const o of OPTS) {
      expect(Number.isFinite(bilinear(exam, NaN, Infinity, o))).toBe(true);
      expect(Number.isFinite(nearest(exam, NaN, -Infinity, o))).toBe(true);
    }
  });
});

describe('2 × 2 and 64 × 64 grids', () => {
  it('2 × 2 corner-aligned is the textbook (1−u)(1−v)a + u(1−v)b + (1−u)v c + uv d', () => {
    const g = makeGrid(2, 2, (i, j) => [3, -1, 7, 10][j * 2 + i]);
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (u, v) => {
          const ref = (1 - u) * (1 - v) * 3 + u * (1 - v) * -1 + (1 - u) * v * 7 + u * v * 10;
          return Math.abs(bilinear(g, u, v, EXAM_LOOKUP) - ref) <= 1e-13;
        },
      ),
    );
    expect(nearest(g, 0.49, 0.51, EXAM_LOOKUP)).toBe(7);
    expect(nearest(g, 0.5, 0.5, EXAM_LOOKUP)).toBe(10); // ties go to the larger index
  });

  it('64 × 64: a bilinear function of the node coordinates is reproduced; random data matches a direct formula', () => {
    const f = (u: number, v: number) => 2 - 3 * u + 5 * v + 7 * u * v;
    const g = makeGrid(64, 64, (i, j) => f(i / 63, j / 63));
    const r = randomGrid(64, 64, 9);
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (u, v) => {
          if (Math.abs(bilinear(g, u, v, EXAM_LOOKUP) - f(u, v)) > 1e-12) return false;
          // independent formula for the random grid, texel centres + clamp
          const su = Math.min(Math.max(u * 64 - 0.5, 0), 63);
          const sv = Math.min(Math.max(v * 64 - 0.5, 0), 63);
          const i0 = Math.min(Math.floor(su), 62);
          const j0 = Math.min(Math.floor(sv), 62);
          const a = su - i0;
          const b = sv - j0;
          const ref =
            (1 - a) * (1 - b) * texel(r, i0, j0) +
            a * (1 - b) * texel(r, i0 + 1, j0) +
            (1 - a) * b * texel(r, i0, j0 + 1) +
            a * b * texel(r, i0 + 1, j0 + 1);
          return Math.abs(bilinear(r, u, v, { align: 'center', vflip: false, wrap: 'clamp' }) - ref) <= 1e-14;
        },
      ),
    );
  });
});

const gridArb: fc.Arbitrary<TextureGrid> = fc
  .record({
    w: fc.integer({ min: 2, max: 12 }),
    h: fc.integer({ min: 2, max: 12 }),
    seed: fc.integer({ min: 0, max: 1000 }),
  })
  .map(({ w, h, seed }) => randomGrid(w, h, seed));
const optsArb = fc.constantFrom(...OPTS);
const coordArb = fc.oneof(
  fc.double({ min: -3, max: 4, noNaN: true }),
  fc.constantFrom(0, 1, 2 ** -53, 1 - 2 ** -53, 0.5, -1, 2),
);

describe('properties over all conventions and wrap modes', () => {
  it('bilinear lies within the min/max of its four taps; weights are ≥ 0 and sum to 1; fast = stencil', () => {
    fc.assert(
      fc.property(gridArb, optsArb, coordArb, coordArb, (g, o, u, v) => {
        const s = bilinearStencil(g, u, v, o);
        const lo = Math.min(s.t00, s.t10, s.t01, s.t11);
        const hi = Math.max(s.t00, s.t10, s.t01, s.t11);
        if (!(s.value >= lo - 1e-15 && s.value <= hi + 1e-15)) return false;
        const ws = [s.w00, s.w10, s.w01, s.w11];
        if (ws.some((w) => !(w >= 0 && w <= 1))) return false;
        if (Math.abs(ws.reduce((a, b) => a + b, 0) - 1) > 1e-15) return false;
        if (!(s.fu >= 0 && s.fu <= 1 && s.fv >= 0 && s.fv <= 1)) return false;
        if (!(s.u0 <= s.u + 1e-15 && s.u <= s.u1 + 1e-15 && s.v0 <= s.v + 1e-15 && s.v <= s.v1 + 1e-15))
          return false;
        if (Math.abs(bilinearSteps(s).c - s.value) > 1e-12) return false;
        if (!Object.is(bilinear(g, u, v, o), s.value)) return false;
        const n = nearestStencil(g, u, v, o);
        if (!Object.is(nearestValueFast(g, u, v, o), n.value)) return false;
        return texel(g, n.i, n.j) === n.value;
      }),
    );
  });

  it('the nearest node is at least as close as every stencil node (corner alignment, inside [0, 1])', () => {
    fc.assert(
      fc.property(
        gridArb,
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (g, u, v) => {
          const n = nearestStencil(g, u, v, EXAM_LOOKUP);
          const s = bilinearStencil(g, u, v, EXAM_LOOKUP);
          const d = Math.max(Math.abs(n.nodeU - u), Math.abs(n.nodeV - v));
          return d <= Math.max(s.du, s.dv) / 2 + 1e-12;
        },
      ),
    );
  });

  it('reproduces linear functions a + b·i + c·j exactly away from clamped borders', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 2, max: 64 }),
        fc.integer({ min: 2, max: 64 }),
        fc.double({ min: -10, max: 10, noNaN: true }),
        fc.double({ min: -10, max: 10, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (w, h, b, c, u, v) => {
          const g = makeGrid(w, h, (i, j) => 1 + b * i + c * j);
          const corner = bilinear(g, u, v, EXAM_LOOKUP);
          const refCorner = 1 + b * u * (w - 1) + c * v * (h - 1);
          if (Math.abs(corner - refCorner) > 1e-11 * (1 + Math.abs(refCorner))) return false;
          // texel centres: s = uN − ½ clamped to [0, N − 1]
          const s = Math.min(Math.max(u * w - 0.5, 0), w - 1);
          const t = Math.min(Math.max(v * h - 0.5, 0), h - 1);
          const centre = bilinear(g, u, v, { align: 'center', vflip: false, wrap: 'clamp' });
          return Math.abs(centre - (1 + b * s + c * t)) <= 1e-11 * (1 + Math.abs(centre));
        },
      ),
    );
  });

  it('seam continuity: with texel centres and repeat, lookups just left of u = 1 and just right of u = 0 agree', () => {
    fc.assert(
      fc.property(
        gridArb,
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1e-6, noNaN: true }),
        (g, v, d) => {
          const o: LookupOptions = { align: 'center', vflip: false, wrap: 'repeat' };
          const a = bilinear(g, 1 - d, v, o);
          const b = bilinear(g, d, v, o);
          return Math.abs(a - b) <= 2 * d * g.width * 1 + 1e-12; // values in [0, 1]: Lipschitz ≤ N per unit u
        },
      ),
    );
  });

  it('sphere seam: points just below and just above the +x axis map to u near 1 and u = small, always < 1', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 1e-300, max: 1e-6, noNaN: true }),
        fc.double({ min: -1, max: 1, noNaN: true }),
        (e, z) => {
          const a = sphericalUV(1, -e, z);
          const b = sphericalUV(1, e, z);
          if (!a.ok || !b.ok) return false;
          if (!(a.u < 1 && a.u >= 0 && b.u >= 0 && b.u < 1)) return false;
          // the two sides are within ~e/(2π) of the seam, on opposite ends of [0, 1)
          const o: LookupOptions = { align: 'center', vflip: false, wrap: 'repeat' };
          const g = randomGrid(8, 8, 5);
          return Math.abs(bilinear(g, a.u, a.v, o) - bilinear(g, b.u, b.v, o)) <= 1e-5;
        },
      ),
    );
  });
});
