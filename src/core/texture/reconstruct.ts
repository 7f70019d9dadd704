/**
 * The whole texture reconstructed as an image: a nearest or bilinear lookup at every pixel's
 * centre, computed separably (per column and per row) with exactly the arithmetic of the single
 * lookups in ./nearest.ts and ./bilinear.ts, so every pixel equals the lookup bit for bit.
 */
import { addressCoord, addressIndex } from './addressing';
import type { TextureGrid } from './grid';
import type { LookupOptions } from './lookupOptions';

/** Which reconstruction filter. */
export type Filter = 'nearest' | 'bilinear';

type PixelWindow = { uMin: number; uMax: number; vMin: number; vMax: number };

/** The u of each pixel column's centre and the v (flipped when opts.vflip) of each row's, as {@link reconstructInto} samples them. */
function pixelCoords(
  opts: LookupOptions,
  width: number,
  height: number,
  window: PixelWindow,
): { us: Float64Array; vs: Float64Array } {
  const su = (window.uMax - window.uMin) / width;
  const sv = (window.vMax - window.vMin) / height;
  const us = new Float64Array(width);
  for (let px = 0; px < width; px++) us[px] = window.uMin + (px + 0.5) * su;
  const vs = new Float64Array(height);
  for (let py = 0; py < height; py++) {
    const v = window.vMax - (py + 0.5) * sv;
    vs[py] = opts.vflip ? 1 - v : v;
  }
  return { us, vs };
}

/** Per pixel column the texel column, per row the texel row's offset j · width, of nearestValueFast at those coordinates. */
function nearestTaps(
  grid: TextureGrid,
  opts: LookupOptions,
  us: Float64Array,
  vs: Float64Array,
): { col: Int32Array; rowOff: Int32Array } {
  const w = grid.width;
  const h = grid.height;
  const col = new Int32Array(us.length);
  const rowOff = new Int32Array(vs.length);
  if (opts.align === 'corner') {
    for (let px = 0; px < us.length; px++) col[px] = Math.round(addressCoord(us[px], opts.wrap) * (w - 1));
    for (let py = 0; py < vs.length; py++)
      rowOff[py] = Math.round(addressCoord(vs[py], opts.wrap) * (h - 1)) * w;
  } else {
    for (let px = 0; px < us.length; px++) {
      const u = us[px];
      col[px] = addressIndex(Math.floor((Number.isFinite(u) ? u : 0) * w), w, opts.wrap);
    }
    for (let py = 0; py < vs.length; py++) {
      const vv = vs[py];
      rowOff[py] = addressIndex(Math.floor((Number.isFinite(vv) ? vv : 0) * h), h, opts.wrap) * w;
    }
  }
  return { col, rowOff };
}

/**
 * Where each pixel of a nearest reconstruction ({@link reconstructInto}) reads the grid: the pixel
 * (px, py) is grid.values[rowOff[py] + col[px]]. For images coloured per texel instead of per pixel.
 */
export function nearestPixelTaps(
  grid: TextureGrid,
  opts: LookupOptions,
  width: number,
  height: number,
  window: PixelWindow = { uMin: 0, uMax: 1, vMin: 0, vMax: 1 },
): { col: Int32Array; rowOff: Int32Array } {
  const { us, vs } = pixelCoords(opts, width, height, window);
  return nearestTaps(grid, opts, us, vs);
}

/**
 * One axis of a bilinear lookup for each coordinate in `cs` (texel count n): the two taps and the
 * weight of the second, with exactly the arithmetic of {@link bilinear} for that axis.
 */
function bilinearTaps(
  cs: ArrayLike<number>,
  n: number,
  opts: LookupOptions,
): { t0: Int32Array; t1: Int32Array; f: Float64Array } {
  const len = cs.length;
  const t0 = new Int32Array(len);
  const t1 = new Int32Array(len);
  const f = new Float64Array(len);
  if (opts.align === 'corner') {
    for (let k = 0; k < len; k++) {
      const s = addressCoord(cs[k], opts.wrap) * (n - 1);
      const i0 = Math.min(Math.floor(s), n - 2);
      t0[k] = i0;
      t1[k] = i0 + 1;
      f[k] = s - i0;
    }
  } else {
    for (let k = 0; k < len; k++) {
      const c = cs[k];
      const s = (Number.isFinite(c) ? c : 0) * n - 0.5;
      const r = Math.floor(s);
      f[k] = s - r;
      t0[k] = addressIndex(r, n, opts.wrap);
      t1[k] = addressIndex(r + 1, n, opts.wrap);
    }
  }
  return { t0, t1, f };
}

/**
 * Reconstruct the whole texture as an image: out[py · width + px] = lookup at the pixel centre
 * u = (px + ½)/width, v = 1 − (py + ½)/height (image rows top to bottom, v = 1 on top), over the
 * window [uMin, uMax] × [vMin, vMax] of (u, v) (default [0, 1]²). Batched, writes into the
 * caller's buffer (length ≥ width · height). Returns out.
 *
 * A lookup is separable: its column part (taps and weight) depends on u only and its row part on
 * v only. So each column's and each row's part is computed once, with exactly the arithmetic of
 * {@link bilinear} / {@link nearestValueFast} for that coordinate, and the pixels combine them in
 * the same order: every pixel is bit for bit the lookup at its centre, in a plain loop over typed
 * arrays (fast even on its first run, when the page loads).
 */
export function reconstructInto(
  grid: TextureGrid,
  opts: LookupOptions,
  filter: Filter,
  width: number,
  height: number,
  out: Float64Array,
  window: { uMin: number; uMax: number; vMin: number; vMax: number } = { uMin: 0, uMax: 1, vMin: 0, vMax: 1 },
): Float64Array {
  const w = grid.width;
  const h = grid.height;
  const vals = grid.values;
  const { us, vs } = pixelCoords(opts, width, height, window);
  if (filter === 'nearest') {
    const { col, rowOff } = nearestTaps(grid, opts, us, vs);
    for (let py = 0; py < height; py++) {
      const row = py * width;
      const off = rowOff[py];
      for (let px = 0; px < width; px++) out[row + px] = vals[off + col[px]];
    }
    return out;
  }
  // bilinear: per column i0, i1, fu; per row j0, j1, fv (as in bilinear)
  const { t0: i0s, t1: i1s, f: fus } = bilinearTaps(us, w, opts);
  const { t0: j0s, t1: j1s, f: fvs } = bilinearTaps(vs, h, opts);
  for (let py = 0; py < height; py++) {
    const row = py * width;
    const o0 = j0s[py] * w;
    const o1 = j1s[py] * w;
    const fv = fvs[py];
    const gv = 1 - fv;
    for (let px = 0; px < width; px++) {
      const i0 = i0s[px];
      const i1 = i1s[px];
      const fu = fus[px];
      const gu = 1 - fu;
      const lower = gu * vals[o0 + i0] + fu * vals[o0 + i1];
      const upper = gu * vals[o1 + i0] + fu * vals[o1 + i1];
      out[row + px] = gv * lower + fv * upper;
    }
  }
  return out;
}
