import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  EXAM_GRID_TEXT,
  checkerGrid,
  examGrid,
  formatGrid,
  gradientGrid,
  gridFromRows,
  gridRange,
  gridToRows,
  parseGrid,
  randomGrid,
  texel,
} from '../../../src/core/texture';

describe('grid layout', () => {
  it('stores the exam grid with row 0 at v = 0: value(i, j) = 21 − 5j + i', () => {
    const g = examGrid();
    expect(g.width).toBe(5);
    expect(g.height).toBe(5);
    for (let j = 0; j < 5; j++) for (let i = 0; i < 5; i++) expect(texel(g, i, j)).toBe(21 - 5 * j + i);
    // the printed form, rows top (v = 1) to bottom
    expect(gridToRows(g)[0]).toEqual([1, 2, 3, 4, 5]);
    expect(gridToRows(g)[4]).toEqual([21, 22, 23, 24, 25]);
    expect(EXAM_GRID_TEXT).toBe('1,2,3,4,5;6,7,8,9,10;11,12,13,14,15;16,17,18,19,20;21,22,23,24,25');
  });

  it('gridFromRows / gridToRows / formatGrid / parseGrid round-trip (property)', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 2, max: 9 }),
        fc.integer({ min: 2, max: 9 }),
        fc.array(fc.double({ min: -1e6, max: 1e6, noNaN: true, noDefaultInfinity: true }), {
          minLength: 81,
          maxLength: 81,
        }),
        (w, h, pool) => {
          const rows = Array.from({ length: h }, (_, r) =>
            Array.from({ length: w }, (_, c) => pool[r * 9 + c] + 0),
          );
          const g = gridFromRows(rows);
          const p = parseGrid(formatGrid(g));
          if (!p.ok) return false;
          const back = gridToRows(p.grid);
          return back.every((row, r) => row.every((x, c) => Object.is(x, rows[r][c])));
        },
      ),
    );
  });
});

describe('parseGrid', () => {
  it('accepts whitespace, signs, exponents and one trailing semicolon', () => {
    const p = parseGrid(' 1, -2.5 ; +3e1 ,.5 ;');
    expect(p.ok).toBe(true);
    if (p.ok)
      expect(gridToRows(p.grid)).toEqual([
        [1, -2.5],
        [30, 0.5],
      ]);
  });

  it('rejects bad text with a message that names the problem', () => {
    const bad: [string, RegExp][] = [
      ['', /empty/],
      ['   ', /empty/],
      ['1,2,3', /1 row/],
      ['1;2', /Row 1 has 1 value/],
      ['1,2;3', /ragged: row 2 has 1 value, row 1 has 2/],
      ['1,2;3,4,5', /ragged/],
      ['1,abc;3,4', /Row 1, column 2 is not a number: "abc"/],
      ['1,2;3,', /Row 2, column 2 is empty/],
      ['1,2;3,0x10', /not a number/],
      ['1,2;3,NaN', /not a number/],
      ['1,2;3,Infinity', /not a number/],
      ['1,2;3,1e999', /too large/],
      [Array.from({ length: 65 }, () => '1,2').join(';'), /65 rows/],
      [[Array(65).fill(1).join(','), Array(65).fill(1).join(',')].join(';'), /65 values/],
    ];
    for (const [text, re] of bad) {
      const p = parseGrid(text);
      expect(p.ok, text.slice(0, 20)).toBe(false);
      if (!p.ok) expect(p.message).toMatch(re);
    }
  });

  it('accepts the extreme sizes 2 × 2 and 64 × 64', () => {
    expect(parseGrid('1,2;3,4').ok).toBe(true);
    const big = Array.from({ length: 64 }, (_, r) =>
      Array.from({ length: 64 }, (_, c) => r * 64 + c).join(','),
    ).join(';');
    const p = parseGrid(big);
    expect(p.ok).toBe(true);
    if (p.ok) {
      expect(p.grid.width).toBe(64);
      expect(texel(p.grid, 0, 63)).toBe(0); // top-left of the text is (i = 0, j = 63)
      expect(texel(p.grid, 63, 0)).toBe(64 * 64 - 1);
    }
  });
});

describe('presets', () => {
  it('checkerboard alternates, gradient runs 0 → 1 linearly, random is seeded and in [0, 1]', () => {
    const c = checkerGrid(4, 3);
    expect(texel(c, 0, 0)).toBe(1);
    expect(texel(c, 1, 0)).toBe(0);
    expect(texel(c, 1, 1)).toBe(1);
    const g = gradientGrid(5, 3);
    expect(texel(g, 0, 0)).toBe(0);
    expect(texel(g, 4, 2)).toBe(1);
    expect(texel(g, 2, 1)).toBeCloseTo(0.5, 15);
    const a = randomGrid(8, 8, 42);
    const b = randomGrid(8, 8, 42);
    const d = randomGrid(8, 8, 43);
    expect(Array.from(a.values)).toEqual(Array.from(b.values));
    expect(Array.from(a.values)).not.toEqual(Array.from(d.values));
    const r = gridRange(a);
    expect(r.min).toBeGreaterThanOrEqual(0);
    expect(r.max).toBeLessThanOrEqual(1);
    expect(gridRange(examGrid())).toEqual({ min: 1, max: 25 });
  });
});
