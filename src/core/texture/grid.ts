/**
 * A texture as a grid of scalar values, its text form (the `grid` URL parameter) and presets.
 *
 * Layout (one convention everywhere in the app):
 * - `values[j * width + i]` is the texel / node in column i (u grows with i, left to right) and
 *   row j, where **row j = 0 is at v = 0, the bottom** (v grows upward with j), as in the exam's
 *   value(i, j) = 21 − 5j + i.
 * - The text form lists rows **top to bottom** (v = 1 first), the way the exam prints the grid and
 *   the way a person reads it: rows separated by `;`, values by `,`.
 */
import { fail, type Failure } from '../failure';
import { Rng } from '../random';

/** A width × height grid of finite values; see the module comment for the layout. */
export interface TextureGrid {
  readonly width: number;
  readonly height: number;
  /** Row-major, row 0 = bottom (v = 0); length width · height. */
  readonly values: Float64Array;
}

/** Smallest and largest grid side the app accepts. */
export const MIN_GRID_SIZE = 2;
export const MAX_GRID_SIZE = 64;

/** The value in column i, row j (row 0 at v = 0). No bounds check: the caller addresses first. */
export function texel(grid: TextureGrid, i: number, j: number): number {
  return grid.values[j * grid.width + i];
}

/** A grid whose node (i, j) holds f(i, j). Domain: integer sides ≥ 1. */
export function makeGrid(width: number, height: number, f: (i: number, j: number) => number): TextureGrid {
  const values = new Float64Array(width * height);
  for (let j = 0; j < height; j++) for (let i = 0; i < width; i++) values[j * width + i] = f(i, j);
  return { width, height, values };
}

/**
 * A grid from rows listed top to bottom (rows[0] is v = 1). Assumes a rectangular array of
 * finite numbers; use {@link parseGrid} for untrusted text.
 */
export function gridFromRows(rows: readonly (readonly number[])[]): TextureGrid {
  const height = rows.length;
  const width = height > 0 ? rows[0].length : 0;
  return makeGrid(width, height, (i, j) => rows[height - 1 - j][i]);
}

/** The rows of a grid, top to bottom (inverse of {@link gridFromRows}). */
export function gridToRows(grid: TextureGrid): number[][] {
  const rows: number[][] = [];
  for (let j = grid.height - 1; j >= 0; j--) {
    const row: number[] = [];
    for (let i = 0; i < grid.width; i++) row.push(texel(grid, i, j));
    rows.push(row);
  }
  return rows;
}

/** The text form: rows top to bottom, `;` between rows, `,` between values, each as String(x). */
export function formatGrid(grid: TextureGrid): string {
  return gridToRows(grid)
    .map((r) => r.map((x) => String(x)).join(','))
    .join(';');
}

const NUMBER_RE = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

/** Result of {@link parseGrid}: the grid, or a message naming the first problem. */
export type ParseGridResult = { ok: true; grid: TextureGrid } | Failure<'empty' | 'size' | 'ragged' | 'cell'>;

/**
 * Parse the text form (rows top to bottom, `;` between rows, `,` between values; whitespace
 * ignored; one trailing `;` allowed). Rejects, with a message that names the row and column
 * (counted from 1, top row first): an empty text, a non-numeric or empty cell (only plain decimal
 * numbers such as `-1.5e3` are accepted), a non-finite value, ragged rows, and sides outside
 * {@link MIN_GRID_SIZE} … {@link MAX_GRID_SIZE}.
 */
export function parseGrid(text: string): ParseGridResult {
  let t = text.trim();
  if (t.endsWith(';')) t = t.slice(0, -1);
  if (t.length === 0) return fail('empty', 'The grid is empty.');
  const rowTexts = t.split(';');
  if (rowTexts.length < MIN_GRID_SIZE || rowTexts.length > MAX_GRID_SIZE) {
    return fail(
      'size',
      `The grid has ${rowTexts.length} row${rowTexts.length === 1 ? '' : 's'}; it needs ${MIN_GRID_SIZE} to ${MAX_GRID_SIZE}.`,
    );
  }
  const rows: number[][] = [];
  let width = -1;
  for (let r = 0; r < rowTexts.length; r++) {
    const cells = rowTexts[r].split(',');
    if (width < 0) {
      width = cells.length;
      if (width < MIN_GRID_SIZE || width > MAX_GRID_SIZE) {
        return fail(
          'size',
          `Row 1 has ${width} value${width === 1 ? '' : 's'}; rows need ${MIN_GRID_SIZE} to ${MAX_GRID_SIZE}.`,
        );
      }
    } else if (cells.length !== width) {
      return fail(
        'ragged',
        `The grid is ragged: row ${r + 1} has ${cells.length} value${cells.length === 1 ? '' : 's'}, row 1 has ${width}.`,
      );
    }
    const row: number[] = [];
    for (let c = 0; c < cells.length; c++) {
      const s = cells[c].trim();
      if (!NUMBER_RE.test(s)) {
        const shown = s.length > 12 ? `${s.slice(0, 12)}…` : s;
        return fail(
          'cell',
          s === ''
            ? `Row ${r + 1}, column ${c + 1} is empty.`
            : `Row ${r + 1}, column ${c + 1} is not a number: "${shown}".`,
        );
      }
      const x = Number(s);
      if (!Number.isFinite(x))
        return fail('cell', `Row ${r + 1}, column ${c + 1} is too large: "${s.slice(0, 12)}".`);
      row.push(x);
    }
    rows.push(row);
  }
  return { ok: true, grid: gridFromRows(rows) };
}

/** The exam's 5 × 5 texture: value(i, j) = 21 − 5j + i at corner-aligned nodes (i/4, j/4). */
export function examGrid(): TextureGrid {
  return makeGrid(5, 5, (i, j) => 21 - 5 * j + i);
}

/** The exam's grid in text form (rows top to bottom): "1,2,3,4,5;6,…;21,22,23,24,25". */
export const EXAM_GRID_TEXT = formatGrid(examGrid());

/** A checkerboard of 0 and 1, with (0, 0) = 1 (bottom-left). */
export function checkerGrid(width: number, height: number): TextureGrid {
  return makeGrid(width, height, (i, j) => ((i + j) % 2 === 0 ? 1 : 0));
}

/**
 * A diagonal gradient from 0 (bottom-left) to 1 (top-right): (i/(w−1) + j/(h−1)) / 2, a linear
 * function of the node coordinates, so bilinear filtering with corner-aligned nodes reproduces it
 * exactly.
 */
export function gradientGrid(width: number, height: number): TextureGrid {
  return makeGrid(width, height, (i, j) => (i / (width - 1) + j / (height - 1)) / 2);
}

/** Values uniform on {0, 0.01, …, 1} (two decimals, so they read well), from a seeded generator. */
export function randomGrid(width: number, height: number, seed: number): TextureGrid {
  const rng = new Rng(seed, 0x7e7);
  return makeGrid(width, height, () => Math.floor(rng.nextFloat() * 101) / 100);
}

/** Smallest and largest value of a grid (for colour scales). */
export function gridRange(grid: TextureGrid): { min: number; max: number } {
  let min = Infinity;
  let max = -Infinity;
  for (let k = 0; k < grid.values.length; k++) {
    const x = grid.values[k];
    if (x < min) min = x;
    if (x > max) max = x;
  }
  return { min, max };
}
