/**
 * The texture as an image for the canvases: a reconstruction coloured by value with the project's
 * colormap.
 */
import {
  gridRange,
  nearestPixelTaps,
  reconstructInto,
  type Filter,
  type LookupOptions,
  type TextureGrid,
} from '../../core/texture';
import { colorizeInto } from '../../core/colormap';

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
  const img = new Uint8ClampedArray(w * h * 4);
  if (filter === 'nearest') {
    // every pixel shows one texel's value: colour the texels once (texelColours, so the same
    // bytes as colouring each pixel's value), then copy each pixel's texel colour as one word
    const lut32 = new Uint32Array(texelColours(grid, range).buffer);
    const img32 = new Uint32Array(img.buffer);
    const { col, rowOff } = nearestPixelTaps(grid, opts, w, h, window);
    for (let py = 0; py < h; py++) {
      const row = py * w;
      if (py > 0 && rowOff[py] === rowOff[py - 1]) {
        img32.copyWithin(row, row - w, row);
        continue;
      }
      const off = rowOff[py];
      for (let px = 0; px < w; px++) img32[row + px] = lut32[off + col[px]];
    }
    return img;
  }
  reconstructInto(grid, opts, filter, w, h, scratch, window);
  colorizeInto(scratch, w * h, range.min, range.max, img);
  return img;
}

/** Pixels [x, x + w) × [y, y + h) of an image, all showing grid.values[texel]. */
export interface TexelRect {
  x: number;
  y: number;
  w: number;
  h: number;
  texel: number;
}

/**
 * The 'nearest' image of {@link textureImage} as one rectangle per texel region in view: the runs
 * of pixel columns that read one texel column, crossed with the runs of rows that read one texel
 * row (rows top to bottom, as there). Filled with each texel's colour, they give the same pixels as
 * writing them one by one, in a few dozen canvas calls for a small grid instead of w × h writes.
 * Null when there would be more than `maxRects` (a grid finer than the image).
 */
export function nearestRects(
  grid: TextureGrid,
  opts: LookupOptions,
  w: number,
  h: number,
  window?: { uMin: number; uMax: number; vMin: number; vMax: number },
  maxRects = 4096,
): TexelRect[] | null {
  const { col, rowOff } = nearestPixelTaps(grid, opts, w, h, window);
  const runs = (a: Int32Array, n: number): [number, number][] => {
    const out: [number, number][] = [];
    for (let k = 0; k < n;) {
      let e = k + 1;
      while (e < n && a[e] === a[k]) e++;
      out.push([k, e]);
      k = e;
    }
    return out;
  };
  const cols = runs(col, w);
  const rows = runs(rowOff, h);
  if (cols.length * rows.length > maxRects) return null;
  const out: TexelRect[] = [];
  for (const [y0, y1] of rows)
    for (const [x0, x1] of cols)
      out.push({ x: x0, y: y0, w: x1 - x0, h: y1 - y0, texel: rowOff[y0] + col[x0] });
  return out;
}

/** Each texel's colour on [range.min, range.max], as RGBA bytes (texel k at 4k), as textureImage colours them. */
export function texelColours(
  grid: TextureGrid,
  range: { min: number; max: number } = gridRange(grid),
): Uint8ClampedArray {
  const n = grid.values.length;
  const lut = new Uint8ClampedArray(4 * n);
  colorizeInto(grid.values, n, range.min, range.max, lut);
  return lut;
}
