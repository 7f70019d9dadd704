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
    // every pixel shows one texel's value: colour the texels once (colorizeInto, so the same
    // bytes as colouring each pixel's value), then copy each pixel's texel colour as one word
    const n = grid.values.length;
    const lut = new Uint8ClampedArray(4 * n);
    colorizeInto(grid.values, n, range.min, range.max, lut);
    const lut32 = new Uint32Array(lut.buffer);
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
