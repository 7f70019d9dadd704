/**
 * The texture scene's model: the grid and the lookups the URL parameters describe, as pure
 * functions (no DOM, no React) calling the core (`src/core/texture`). The views only draw what
 * these and their neighbours (./sphere.ts, ./path.ts, ./pathProfile.ts, ./creases.ts,
 * ./readouts.ts, ./textureImage.ts) return.
 */
import {
  addressCoord,
  bilinearStencil,
  bilinearSteps,
  checkerGrid,
  examGrid,
  formatGrid,
  gradientGrid,
  nearestStencil,
  parseGrid,
  randomGrid,
  type BilinearStencil,
  type BilinearSteps,
  type LookupOptions,
  type NearestStencil,
  type TextureGrid,
} from '../../core/texture';
import { formatRounded } from '../../core/format';
import type { ParamProblem, ParamValues } from '../../kit/params';
import { GRID_TEXT_MAX, type TextureSchema } from './params';

export type TextureParams = ParamValues<TextureSchema>;

/** A texture as the figures draw it: the grid, the lookup conventions, and the range of its values. */
export interface ShownTexture {
  grid: TextureGrid;
  opts: LookupOptions;
  range: { min: number; max: number };
}

/** Where the grid came from, and what went wrong if the `grid` text could not be used. */
export interface GridSource {
  grid: TextureGrid;
  /**
   * The parameters that could not be used as given (the `grid` text; the exam's grid is used
   * instead), each with the parser's message; empty when all were usable.
   */
  problems: ParamProblem[];
  /** True when the grid is exactly the exam's 5 × 5 grid. */
  isExam: boolean;
}

/** The grid the parameters describe (never throws; a bad `grid` text falls back to the exam's grid). */
export function resolveGrid(p: Pick<TextureParams, 'grid' | 'preset' | 'size' | 'seed'>): GridSource {
  const preset = p.preset;
  let grid: TextureGrid;
  const problems: ParamProblem[] = [];
  if (preset === 'checker') grid = checkerGrid(p.size, p.size);
  else if (preset === 'gradient') grid = gradientGrid(p.size, p.size);
  else if (preset === 'random') grid = randomGrid(p.size, p.size, p.seed);
  else {
    const r = parseGrid(p.grid);
    if (r.ok) grid = r.grid;
    else {
      problems.push({ name: 'grid', message: r.message });
      grid = examGrid();
    }
  }
  return { grid, problems, isExam: sameGrid(grid, examGrid()) };
}

/** Equal sides and equal values. */
export function sameGrid(a: TextureGrid, b: TextureGrid): boolean {
  if (a.width !== b.width || a.height !== b.height) return false;
  for (let k = 0; k < a.values.length; k++) if (a.values[k] !== b.values[k]) return false;
  return true;
}

/** A copy of the grid with node (i, j) set to x. */
export function withCell(grid: TextureGrid, i: number, j: number, x: number): TextureGrid {
  const values = new Float64Array(grid.values);
  values[j * grid.width + i] = x;
  return { width: grid.width, height: grid.height, values };
}

/** The grid's text form if it fits in a URL parameter, else null. */
export function gridTextIfFits(grid: TextureGrid): string | null {
  const t = formatGrid(grid);
  return t.length <= GRID_TEXT_MAX ? t : null;
}

export function lookupOptions(p: Pick<TextureParams, 'align' | 'vflip' | 'wrap'>): LookupOptions {
  return { align: p.align, vflip: p.vflip, wrap: p.wrap };
}

/** A lookup at one (u, v): both filters, with stencils and the key's steps. */
export interface Lookup {
  u: number;
  v: number;
  near: NearestStencil;
  bil: BilinearStencil;
  steps: BilinearSteps;
}

export function lookupAt(grid: TextureGrid, u: number, v: number, opts: LookupOptions): Lookup {
  const bil = bilinearStencil(grid, u, v, opts);
  return { u, v, near: nearestStencil(grid, u, v, opts), bil, steps: bilinearSteps(bil) };
}

/** The equivalent in-window point of a query, and the lookup drawn there (texture frame, no flip). */
export function drawnLookup(grid: TextureGrid, u: number, v: number, opts: LookupOptions): Lookup {
  const vt = opts.vflip ? 1 - v : v;
  const o = { ...opts, vflip: false };
  return lookupAt(grid, addressCoord(u, opts.wrap), addressCoord(vt, opts.wrap), o);
}

/** Why the query (u, v) was changed before the lookup, in words (empty when it was used as is). */
export function addressingNotes(u: number, v: number, opts: LookupOptions, q: Lookup): string[] {
  const notes: string[] = [];
  const vv = opts.vflip ? 1 - v : v;
  if (opts.vflip) notes.push(`v-flip: v′ = 1 − v = ${formatRounded(vv, 6)}.`);
  const out = (t: number) => t < 0 || t > 1;
  if (opts.align === 'corner') {
    if (out(u))
      notes.push(
        `u = ${formatRounded(u, 6)} is outside [0, 1]; ${opts.wrap} addressing uses u = ${formatRounded(q.bil.u, 6)}.`,
      );
    if (out(vv))
      notes.push(
        `${opts.vflip ? 'v′' : 'v'} = ${formatRounded(vv, 6)} is outside [0, 1]; ${opts.wrap} addressing uses ${formatRounded(q.bil.v, 6)}.`,
      );
  } else {
    const edgeU = q.bil.i0 > q.bil.i1 || q.bil.i0 === q.bil.i1;
    const edgeV = q.bil.j0 > q.bil.j1 || q.bil.j0 === q.bil.j1;
    if (edgeU || edgeV) {
      notes.push(
        `The stencil crosses the texture's ${edgeU && edgeV ? 'corner' : edgeU ? 'left/right edge' : 'top/bottom edge'}: ${opts.wrap} addressing maps the texel indices (columns ${q.bil.i0}, ${q.bil.i1}; rows ${q.bil.j0}, ${q.bil.j1}).`,
      );
    } else if (out(u) || out(vv)) {
      notes.push(`The query is outside [0, 1]; ${opts.wrap} addressing maps the texel indices it lands on.`);
    }
  }
  return notes;
}
