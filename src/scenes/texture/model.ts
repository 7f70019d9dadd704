/**
 * The texture scene's model: pure functions of the URL parameters (no DOM, no React), calling the
 * core (`src/core/texture`). The views only draw what these return.
 */
import {
  addressCoord,
  bilinearStencil,
  bilinearSteps,
  checkerGrid,
  examGrid,
  formatGrid,
  gradientGrid,
  gridRange,
  nearestStencil,
  parseGrid,
  randomGrid,
  reconstructInto,
  sphericalUV,
  type BilinearStencil,
  type BilinearSteps,
  type Filter,
  type LookupOptions,
  type NearestStencil,
  type TextureGrid,
  type WrapMode,
} from '../../core/texture';
import type { ParamValues } from '../../app/params';
import { colorInto, normalizeValue } from './colormap';
import { GRID_TEXT_MAX, type Preset, type TextureSchema } from './params';

export type TextureParams = ParamValues<TextureSchema>;

/** Where the grid came from, and what went wrong if the `grid` text could not be used. */
export interface GridSource {
  grid: TextureGrid;
  /** Set when the `grid` parameter was unusable; the exam's grid is used instead. */
  error: string | null;
  /** True when the grid is exactly the exam's 5 × 5 grid. */
  isExam: boolean;
}

/** The grid the parameters describe (never throws; a bad `grid` text falls back to the exam's grid). */
export function resolveGrid(p: Pick<TextureParams, 'grid' | 'preset' | 'size' | 'seed'>): GridSource {
  const preset = p.preset as Preset;
  let grid: TextureGrid;
  let error: string | null = null;
  if (preset === 'checker') grid = checkerGrid(p.size, p.size);
  else if (preset === 'gradient') grid = gradientGrid(p.size, p.size);
  else if (preset === 'random') grid = randomGrid(p.size, p.size, p.seed);
  else {
    const r = parseGrid(p.grid);
    if (r.ok) grid = r.grid;
    else {
      error = r.error;
      grid = examGrid();
    }
  }
  return { grid, error, isExam: sameGrid(grid, examGrid()) };
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
  return { align: p.align === 'center' ? 'center' : 'corner', vflip: p.vflip, wrap: p.wrap as WrapMode };
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

/** The sphere part: (x, y, z) → (φ, θ) → (u, v), looked up normalized and not. */
export type SphereModel =
  | { ok: false; error: string }
  | {
      ok: true;
      r: number;
      phi: number;
      theta: number;
      pole: boolean;
      /** Lookup at (φ / 2π, θ / π): the exam's intended answer. */
      normalized: Lookup;
      /** Lookup at (φ, θ) in radians: the "forgot to normalize" variant. */
      raw: Lookup;
      /** The one the `normalize` parameter selects (feeds the contract readouts). */
      chosen: Lookup;
    };

export function sphereModel(grid: TextureGrid, p: Pick<TextureParams, 'x' | 'y' | 'z' | 'normalize'>, opts: LookupOptions): SphereModel {
  const s = sphericalUV(p.x, p.y, p.z);
  if (!s.ok) return { ok: false, error: s.error };
  const normalized = lookupAt(grid, s.u, s.v, opts);
  const raw = lookupAt(grid, s.phi, s.theta, opts);
  return { ok: true, r: s.r, phi: s.phi, theta: s.theta, pole: s.pole, normalized, raw, chosen: p.normalize ? normalized : raw };
}

/** The contract readouts of the scene (numbers, or null where they do not apply). */
export interface TextureReadouts {
  nearest: number;
  bilinear: number;
  sphereU: number | null;
  sphereV: number | null;
  sphereBilinear: number | null;
}

export function readouts(q: Lookup, sphere: SphereModel): TextureReadouts {
  return {
    nearest: q.near.value,
    bilinear: q.bil.value,
    sphereU: sphere.ok ? sphere.chosen.u : null,
    sphereV: sphere.ok ? sphere.chosen.v : null,
    sphereBilinear: sphere.ok ? sphere.chosen.bil.value : null,
  };
}

/**
 * True when the sphere part is the exam's Q3(c): the exam's grid and settings, and a point whose
 * direction gives (φ, θ) = (π/4, π/4) to 1e-12. The scene then compares with the key's figures.
 */
export function isExamSphere(src: GridSource, opts: LookupOptions, sphere: SphereModel): boolean {
  return (
    src.isExam &&
    opts.align === 'corner' &&
    !opts.vflip &&
    sphere.ok &&
    Math.abs(sphere.phi - Math.PI / 4) < 1e-12 &&
    Math.abs(sphere.theta - Math.PI / 4) < 1e-12
  );
}

/** Why the query (u, v) was changed before the lookup, in words (empty when it was used as is). */
export function addressingNotes(u: number, v: number, opts: LookupOptions, q: Lookup): string[] {
  const notes: string[] = [];
  const vv = opts.vflip ? 1 - v : v;
  if (opts.vflip) notes.push(`v-flip: v′ = 1 − v = ${fmt(vv)}.`);
  const out = (t: number) => t < 0 || t > 1;
  if (opts.align === 'corner') {
    if (out(u)) notes.push(`u = ${fmt(u)} is outside [0, 1]; ${opts.wrap} addressing uses u = ${fmt(q.bil.u)}.`);
    if (out(vv)) notes.push(`${opts.vflip ? 'v′' : 'v'} = ${fmt(vv)} is outside [0, 1]; ${opts.wrap} addressing uses ${fmt(q.bil.v)}.`);
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

function fmt(x: number): string {
  return String(Number(x.toPrecision(6)));
}

/**
 * The texture as an RGBA image (rows top to bottom, v = vMax on top), coloured by value on
 * [range.min, range.max]. Window defaults to [0, 1]²; `scratch` (length ≥ w·h) avoids allocation.
 */
export function textureImage(
  grid: TextureGrid,
  opts: LookupOptions,
  filter: Filter,
  w: number,
  h: number,
  range: { min: number; max: number } = gridRange(grid),
  window?: { uMin: number; uMax: number; vMin: number; vMax: number },
  scratch: Float64Array = new Float64Array(w * h),
): Uint8ClampedArray {
  reconstructInto(grid, opts, filter, w, h, scratch, window);
  const img = new Uint8ClampedArray(w * h * 4);
  for (let k = 0; k < w * h; k++) {
    colorInto(normalizeValue(scratch[k], range.min, range.max), img, 4 * k);
    img[4 * k + 3] = 255;
  }
  return img;
}

/**
 * The figures the exam's answer key prints for Q3 (quoted only to compare with the live
 * computation, never shown in their place), with the number of decimals the key prints.
 */
export const KEY_PRINTED = {
  nearest: { value: 18, decimals: 0 },
  cu: { value: 17.6, decimals: 1 },
  cl: { value: 22.6, decimals: 1 },
  bilinear: { value: 17.8, decimals: 1 },
  sphereU: { value: 0.125, decimals: 3 },
  sphereV: { value: 0.25, decimals: 2 },
  sphere: { value: 16.5, decimals: 1 },
  sphereRaw: { value: 8.44, decimals: 2 },
} as const;

/** Does the computed value, rounded as the key rounds, equal the key's printed figure? */
export function agreesWithKey(computed: number, printed: { value: number; decimals: number }): boolean {
  return Number(computed.toFixed(printed.decimals)) === printed.value;
}

/** True when the query is the exam's Q3 (a)/(b): the exam's grid and settings at (0.4, 0.24). */
export function isExamQuery(src: GridSource, opts: LookupOptions, u: number, v: number): boolean {
  return src.isExam && opts.align === 'corner' && !opts.vflip && u === 0.4 && v === 0.24;
}
