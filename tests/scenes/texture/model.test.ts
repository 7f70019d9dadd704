import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { parseParams, defaultValues } from '../../../src/kit/params';
import { schema } from '../../../src/scenes/texture/params';
import {
  KEY_PRINTED,
  agreesWithKey,
  isExamQuery,
  isExamSphere,
  readouts,
} from '../../../src/scenes/texture/readouts';
import {
  addressingNotes,
  drawnLookup,
  gridTextIfFits,
  lookupAt,
  lookupOptions,
  resolveGrid,
  withCell,
} from '../../../src/scenes/texture/model';
import { sphereModel } from '../../../src/scenes/texture/sphere';
import { textureImage } from '../../../src/scenes/texture/textureImage';
import {
  EXAM_GRID_TEXT,
  WRAP_MODES,
  examGrid,
  formatGrid,
  randomGrid,
  reconstructInto,
  texel,
  type LookupOptions,
} from '../../../src/core/texture';
import { colorInto, normalizeValue } from '../../../src/core/colormap';

const L = (u: number, v: number) => 21 - 20 * v + 4 * u; // the exam grid as a function of (u, v)

function modelOf(query: string) {
  const p = parseParams(schema, query).values;
  const src = resolveGrid(p);
  const opts = lookupOptions(p);
  const q = lookupAt(src.grid, p.u, p.v, opts);
  const sphere = sphereModel(src.grid, p, opts);
  return { p, src, opts, q, sphere, ro: readouts(q, sphere) };
}

describe('texture scene model', () => {
  it('defaults are the exam: nearest = value(2, 1), bilinear = L(0.4, 0.24), sphere (1/8, 1/4) → L(1/8, 1/4)', () => {
    const m = modelOf('');
    expect(m.src.isExam).toBe(true);
    expect(m.p.grid).toBe(EXAM_GRID_TEXT);
    expect(m.ro.nearest).toBe(21 - 5 + 2);
    expect(m.ro.bilinear).toBeCloseTo(L(0.4, 0.24), 12);
    expect(m.ro.sphereU).toBeCloseTo(1 / 8, 15);
    expect(m.ro.sphereV).toBeCloseTo(1 / 4, 15);
    expect(m.ro.sphereBilinear).toBeCloseTo(L(1 / 8, 1 / 4), 12);
    expect(isExamQuery(m.src, m.opts, m.p.u, m.p.v)).toBe(true);
    expect(isExamSphere(m.src, m.opts, m.sphere)).toBe(true);
    expect(agreesWithKey(m.ro.nearest, KEY_PRINTED.nearest)).toBe(true);
    expect(agreesWithKey(m.ro.bilinear, KEY_PRINTED.bilinear)).toBe(true);
    expect(agreesWithKey(m.q.steps.cu, KEY_PRINTED.cu)).toBe(true);
    expect(agreesWithKey(m.q.steps.cl, KEY_PRINTED.cl)).toBe(true);
  });

  it('normalize=0 reads out (φ, θ) and the lookup there: 21 − 4π, which the key misprints as 8.44', () => {
    const m = modelOf('normalize=0');
    expect(m.ro.sphereU).toBeCloseTo(Math.PI / 4, 15);
    expect(m.ro.sphereV).toBeCloseTo(Math.PI / 4, 15);
    expect(m.ro.sphereBilinear).toBeCloseTo(21 - 4 * Math.PI, 12);
    expect(agreesWithKey(m.ro.sphereBilinear!, KEY_PRINTED.sphereRaw)).toBe(false);
  });

  it('a bad grid falls back to the exam grid with a message; a sphere point at the origin gives no sphere readouts', () => {
    const bad = modelOf('grid=1,2;3');
    expect(bad.src.problems).toEqual([{ name: 'grid', message: expect.stringMatching(/ragged/) }]);
    expect(bad.src.isExam).toBe(true);
    expect(bad.ro.nearest).toBe(18);
    expect(modelOf('grid=1,x;3,4').src.problems[0]?.message).toMatch(/not a number/);
    expect(modelOf('').src.problems).toEqual([]);
    const o = modelOf('x=0&y=0&z=0');
    expect(o.sphere.ok).toBe(false);
    expect([o.ro.sphereU, o.ro.sphereV, o.ro.sphereBilinear]).toEqual([null, null, null]);
  });

  it('presets: size and seed pick generated grids; 64 × 64 is reachable without a grid text', () => {
    const m = modelOf('preset=random&size=64&seed=3');
    expect(m.src.grid.width).toBe(64);
    expect(Array.from(m.src.grid.values)).toEqual(Array.from(randomGrid(64, 64, 3).values));
    expect(gridTextIfFits(m.src.grid)).toBeNull(); // too long for a link
    expect(modelOf('preset=checker&size=2').src.grid.values.length).toBe(4);
    expect(modelOf('preset=exam').src.isExam).toBe(true); // alias of the grid parameter's default
  });

  it('withCell edits one node; gridTextIfFits round-trips small grids', () => {
    const g = withCell(examGrid(), 2, 1, 100);
    expect(texel(g, 2, 1)).toBe(100);
    expect(texel(examGrid(), 2, 1)).toBe(18);
    expect(gridTextIfFits(g)).toBe(formatGrid(g));
  });

  it('the drawn (in-window) lookup has the same bilinear value as the actual one, for every convention (property)', () => {
    const all: LookupOptions[] = [];
    for (const align of ['corner', 'center'] as const)
      for (const vflip of [false, true]) for (const wrap of WRAP_MODES) all.push({ align, vflip, wrap });
    fc.assert(
      fc.property(
        fc.constantFrom(...all),
        fc.double({ min: -4, max: 4, noNaN: true }),
        fc.double({ min: -4, max: 4, noNaN: true }),
        fc.integer({ min: 2, max: 9 }),
        (o, u, v, n) => {
          const g = randomGrid(n, n + 1, n);
          const a = lookupAt(g, u, v, o);
          const d = drawnLookup(g, u, v, o);
          if (!(d.bil.u >= 0 && d.bil.u <= 1 && d.bil.v >= 0 && d.bil.v <= 1)) return false;
          // nearest may differ only at exact ties (a mirrored tie can fall on the other side)
          return Math.abs(a.bil.value - d.bil.value) <= 1e-9;
        },
      ),
    );
  });

  it('addressing notes explain outside queries and the v-flip', () => {
    const m = modelOf('u=1.4&wrap=repeat');
    expect(addressingNotes(m.p.u, m.p.v, m.opts, m.q).join(' ')).toMatch(
      /u = 1\.4 is outside \[0, 1\]; repeat addressing uses u = 0\.4/,
    );
    const f = modelOf('vflip=1');
    expect(addressingNotes(f.p.u, f.p.v, f.opts, f.q).join(' ')).toMatch(/v′ = 1 − v = 0\.76/);
    expect(
      addressingNotes(
        0.4,
        0.24,
        lookupOptions(defaultValues(schema)),
        lookupAt(examGrid(), 0.4, 0.24, lookupOptions(defaultValues(schema))),
      ),
    ).toEqual([]);
  });

  it('textureImage is opaque RGBA of the right size and follows the value order', () => {
    const img = textureImage(examGrid(), lookupOptions(defaultValues(schema)), 'nearest', 5, 5);
    expect(img.length).toBe(100);
    for (let k = 3; k < 100; k += 4) expect(img[k]).toBe(255);
    // top-left is the smallest value (1, darkest), bottom-right the largest (25, brightest)
    const lum = (k: number) => img[4 * k] + img[4 * k + 1] + img[4 * k + 2];
    expect(lum(0)).toBeLessThan(lum(24));
  });

  it('textureImage colours each pixel exactly as colorInto does on its normalized value (flat and NaN ranges included)', () => {
    const g = randomGrid(6, 5, 3);
    const W = 31;
    const H = 19;
    for (const filter of ['nearest', 'bilinear'] as const)
      for (const range of [
        { min: -0.2, max: 0.7 },
        { min: 0.3, max: 0.3 },
        { min: NaN, max: 1 },
        { min: 0.4, max: 0.5 },
      ]) {
        const opts = lookupOptions({ align: 'center', vflip: true, wrap: 'mirror' });
        const win = { uMin: -0.3, uMax: 1.2, vMin: -0.1, vMax: 1.4 };
        const img = textureImage(g, opts, filter, W, H, range, win);
        const vals = reconstructInto(g, opts, filter, W, H, new Float64Array(W * H), win);
        const c = [0, 0, 0];
        for (let k = 0; k < W * H; k++) {
          colorInto(normalizeValue(vals[k], range.min, range.max), c);
          expect([img[4 * k], img[4 * k + 1], img[4 * k + 2], img[4 * k + 3]]).toEqual([
            c[0],
            c[1],
            c[2],
            255,
          ]);
        }
      }
  });
});
