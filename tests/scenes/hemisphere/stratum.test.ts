import { describe, expect, it } from 'vitest';
import { makeLobe } from '../../../src/scenes/hemisphere/lobe';
import {
  CELLS,
  cellBounds,
  cellFromParam,
  cellImage,
  cellOf,
  cellOutline,
  countInCell,
  morphVertices,
  stepCell,
} from '../../../src/scenes/hemisphere/stratum';
import { EXAM_E2PI_M1 } from '../../../src/core/sampling';

const exam = makeLobe('exam', 8)!;

describe('the followed stratum', () => {
  it('reads the URL value: none, a cell, and a fractional index rounded with a sentence', () => {
    expect(cellFromParam(null)).toEqual({ cell: null, problem: null });
    expect(cellFromParam([3, 5])).toEqual({ cell: { i: 3, j: 5 }, problem: null });
    const r = cellFromParam([2.6, 1]);
    expect(r.cell).toEqual({ i: 3, j: 1 });
    expect(r.problem).toMatch(/not two whole numbers/);
  });

  it('cells tile the square; steps stay inside it', () => {
    expect(cellBounds({ i: 3, j: 5 })).toEqual({ xi1: [0.375, 0.5], xi2: [0.625, 0.75] });
    expect(cellOf(0.375, 0.7499)).toEqual({ i: 3, j: 5 });
    expect(cellOf(0.9999999, 0)).toEqual({ i: 7, j: 0 });
    expect(stepCell({ i: 0, j: 7 }, -1, 1)).toEqual({ i: 0, j: 7 });
    expect(stepCell({ i: 3, j: 5 }, 1, -1)).toEqual({ i: 4, j: 4 });
  });

  it("the exam lobe's patch is the θ–φ rectangle of the inversion, with its exact solid angle", () => {
    const c = { i: 3, j: 5 };
    const { xi1, xi2 } = cellBounds(c);
    const img = cellImage(exam, c);
    const th = (x: number) => Math.asin(Math.sqrt(x));
    const ph = (x: number) => Math.log1p(EXAM_E2PI_M1 * x);
    expect(img.theta[0]).toBeCloseTo(th(xi1[0]), 9);
    expect(img.theta[1]).toBeCloseTo(th(xi1[1]), 9);
    expect(img.phi[0]).toBeCloseTo(ph(xi2[0]), 9);
    expect(img.phi[1]).toBeCloseTo(ph(xi2[1]), 9);
    const exact = (Math.cos(th(xi1[0])) - Math.cos(th(xi1[1]))) * (ph(xi2[1]) - ph(xi2[0]));
    expect(Math.abs(img.solidAngle / exact - 1)).toBeLessThan(1e-3);
    expect(img.phiWraps).toBe(false);
  });

  it('uniform sampling gives every cell 1/64 of the hemisphere: density ratio 1', () => {
    const u = makeLobe('uniform', 8)!;
    for (const c of [
      { i: 0, j: 0 },
      { i: 7, j: 3 },
      { i: 4, j: 7 },
    ]) {
      const img = cellImage(u, c);
      expect(Math.abs(img.densityRatio - 1)).toBeLessThan(2e-3);
    }
    // uniform sampling sets z = ξ₁: the last column reaches the pole
    expect(cellImage(u, { i: 7, j: 2 }).pole).toBe(true);
    expect(cellImage(u, { i: 0, j: 2 }).pole).toBe(false);
  });

  it('under the exam lobe the last φ row is squeezed (dense), the first spread (sparse)', () => {
    const first = cellImage(exam, { i: 4, j: 0 });
    const last = cellImage(exam, { i: 4, j: 7 });
    expect(first.densityRatio).toBeLessThan(0.3);
    expect(last.densityRatio).toBeGreaterThan(2);
    expect(last.phi[1]).toBeCloseTo(2 * Math.PI, 9);
  });

  it('concentric-map patches on either side of φ = 0 meet there, without a wrap', () => {
    const cos = makeLobe('cosine', 8)!;
    // rows 3 and 4 meet at ξ₂ = ½, the +x axis; the outer column spans φ = ±(π/4)(¼ / ¾)
    const below = cellImage(cos, { i: 7, j: 3 });
    const above = cellImage(cos, { i: 7, j: 4 });
    expect(below.phi[0]).toBeCloseTo(2 * Math.PI - Math.PI / 12, 6);
    expect(below.phi[1]).toBeCloseTo(2 * Math.PI, 9);
    expect(above.phi[0]).toBeCloseTo(0, 9);
    expect(above.phi[1]).toBeCloseTo(Math.PI / 12, 6);
    expect(below.phiWraps || above.phiWraps).toBe(false);
    // the 64 patches of any exact warp cover the hemisphere once
    let total = 0;
    for (let i = 0; i < CELLS; i++)
      for (let j = 0; j < CELLS; j++) total += cellImage(cos, { i, j }).solidAngle;
    expect(Math.abs(total / (2 * Math.PI) - 1)).toBeLessThan(2e-3);
  });

  it('the outline starts in the square and ends on the unit sphere', () => {
    const { a, b } = cellOutline(exam, { i: 2, j: 6 }, 8);
    const out = new Float32Array(a.length);
    morphVertices(a, b, 0, out);
    for (let k = 0; k < a.length; k += 3) expect(out[k + 2]).toBe(0);
    morphVertices(a, b, 1, out);
    for (let k = 0; k < a.length; k += 3)
      expect(Math.hypot(out[k], out[k + 1], out[k + 2])).toBeCloseTo(1, 6);
  });

  it('the counts of the 64 cells add up to n', () => {
    const scratch = new Float64Array(2 * 1000);
    const n = 5000;
    let total = 0;
    for (let i = 0; i < CELLS; i++)
      for (let j = 0; j < CELLS; j++) total += countInCell('sobol', 3, n, { i, j }, 0, n, scratch);
    expect(total).toBe(n);
    // stratified-like sets fill every cell evenly; independent points vary
    expect(countInCell('sobol', 3, 4096, { i: 3, j: 5 }, 0, 4096, scratch)).toBe(64);
  });
});
