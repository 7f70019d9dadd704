import { describe, expect, it } from 'vitest';
import {
  EXAM_LOOKUP,
  WRAP_MODES,
  bilinear,
  examGrid,
  nearest,
  nearestValueFast,
  randomGrid,
  reconstructInto,
  type LookupOptions,
} from '../../../src/core/texture';

/** The exam's grid as the linear function of its node coordinates (see lookup.test.ts). */
const L = (u: number, v: number) => 21 - 20 * v + 4 * u;
const exam = examGrid();
const OPTS: LookupOptions[] = [];
for (const align of ['corner', 'center'] as const)
  for (const vflip of [false, true]) for (const wrap of WRAP_MODES) OPTS.push({ align, vflip, wrap });

describe('reconstructInto', () => {
  it('fills pixel centres with the lookups, v = 1 on the top row', () => {
    const out = new Float64Array(8 * 4);
    reconstructInto(exam, EXAM_LOOKUP, 'bilinear', 8, 4, out);
    expect(out[0]).toBeCloseTo(L(1 / 16, 1 - 1 / 8), 12);
    expect(out[3 * 8 + 7]).toBeCloseTo(L(15 / 16, 1 / 8), 12);
    reconstructInto(exam, EXAM_LOOKUP, 'nearest', 8, 4, out);
    expect(out[0]).toBe(nearest(exam, 1 / 16, 7 / 8, EXAM_LOOKUP));
    const w = reconstructInto(exam, EXAM_LOOKUP, 'bilinear', 2, 1, new Float64Array(2), {
      uMin: -1,
      uMax: 1,
      vMin: 0,
      vMax: 0.5,
    });
    expect(w[0]).toBeCloseTo(L(0, 0.25), 12); // u = −0.5 clamps to 0
    expect(w[1]).toBeCloseTo(L(0.5, 0.25), 12);
  });

  it('is bit for bit the per-pixel lookup at every pixel centre, for every convention and window', () => {
    const grids = [exam, randomGrid(7, 4, 11), randomGrid(3, 9, 12), randomGrid(2, 2, 13)];
    const windows = [
      { uMin: 0, uMax: 1, vMin: 0, vMax: 1 },
      { uMin: -0.08, uMax: 1.08, vMin: -0.08, vMax: 1.08 },
      { uMin: -2.3, uMax: 3.1, vMin: -1.7, vMax: 2.9 },
      { uMin: 0.1, uMax: 0.1, vMin: 0.9, vMax: 0.2 },
    ];
    for (const g of grids)
      for (const o of OPTS)
        for (const win of windows)
          for (const filter of ['nearest', 'bilinear'] as const) {
            const W = 23;
            const H = 17;
            const out = reconstructInto(g, o, filter, W, H, new Float64Array(W * H), win);
            const su = (win.uMax - win.uMin) / W;
            const sv = (win.vMax - win.vMin) / H;
            for (let py = 0; py < H; py++)
              for (let px = 0; px < W; px++) {
                const u = win.uMin + (px + 0.5) * su;
                const v = win.vMax - (py + 0.5) * sv;
                const want = filter === 'bilinear' ? bilinear(g, u, v, o) : nearestValueFast(g, u, v, o);
                if (!Object.is(out[py * W + px], want))
                  throw new Error(
                    `${filter} ${JSON.stringify(o)} (${px}, ${py}): ${out[py * W + px]} ≠ ${want}`,
                  );
              }
          }
  });
});
