/**
 * FLIP of two 8-bit sRGB images, as the app shows and downloads them: the pixels are read exactly
 * as a PNG of them decodes (./png rgbFromRgba8: alpha dropped, byte/255), so the figures here are
 * the ones NVIDIA's FLIP tool prints for the downloaded files. Also the error map coloured by
 * magma, each error first rounded to the nearest of 256 levels, as the reference tool colours it.
 */
import { colorInto, MAGMA } from '../colormap';
import { DEFAULT_PPD, flipErrorMap } from './flip';
import { rgbFromRgba8, type Rgba8Image } from './png';
import { poolError, type PooledError } from './pooling';

/** The per-pixel FLIP error of `test` against `reference` and its pooled figures. */
export interface FlipMeasure {
  map: Float64Array;
  pooled: PooledError;
}

/** LDR-FLIP of two RGBA8 images of one size (throws a RangeError naming the problem otherwise). */
export function flipOfRgba8(reference: Rgba8Image, test: Rgba8Image, ppd = DEFAULT_PPD): FlipMeasure {
  const map = flipErrorMap(rgbFromRgba8(reference), rgbFromRgba8(test), ppd);
  return { map, pooled: poolError(map) };
}

/** An error map in [0, 1] as an opaque RGBA8 image in magma (0 black … 1 pale yellow). */
export function magmaErrorImage(map: ArrayLike<number>, width: number, height: number): Rgba8Image {
  const data = new Uint8ClampedArray(4 * width * height);
  for (let i = 0; i < width * height; i++) {
    colorInto(Math.round(map[i] * 255) / 255, data, 4 * i, MAGMA);
    data[4 * i + 3] = 255;
  }
  return { width, height, data };
}
