/**
 * How the floor images of #/area-light are shown: radiance v → 8-bit pixels, v / scale clamped to
 * [0, 1], gamma 1/2.2, tinted warm white (255, 240, 205); NaN (a reference with no closed form) as
 * a purple hatch colour. The canvases paint these bytes and the measurement (FLIP, the PNG
 * downloads) reads the same bytes.
 */
import { relMse } from '../../core/image/relMse';
import type { ImageSet } from '../../ui/imageMeasure';
import { STRATEGIES, STRATEGY_LABEL } from './strategies';

/** The largest finite value of the reference: white in every image of one frame (1 if none). */
export function floorScale(reference: ArrayLike<number>): number {
  let scale = 0;
  for (let i = 0; i < reference.length; i++) {
    const v = reference[i];
    if (Number.isFinite(v) && v > scale) scale = v;
  }
  return scale > 0 ? scale : 1;
}

/** RGBA8 pixels of a size × size radiance image at the given white level. */
export function floorPixels(
  img: ArrayLike<number>,
  size: number,
  scale: number,
): Uint8ClampedArray<ArrayBuffer> {
  const d = new Uint8ClampedArray(4 * size * size);
  for (let k = 0; k < size * size; k++) {
    const v = img[k];
    if (!Number.isFinite(v)) {
      d[4 * k] = 120;
      d[4 * k + 1] = 60;
      d[4 * k + 2] = 120;
      d[4 * k + 3] = 255;
      continue;
    }
    const t = Math.pow(Math.min(1, Math.max(0, v / scale)), 1 / 2.2);
    d[4 * k] = Math.round(255 * t);
    d[4 * k + 1] = Math.round(240 * t);
    d[4 * k + 2] = Math.round(205 * t);
    d[4 * k + 3] = 255;
  }
  return d;
}

/** One frame of the floor images (reference and one mean image per strategy) as the measurement sees it. */
export function floorImageSet(frame: {
  size: number;
  spp: number;
  reference: Float32Array;
  images: Float32Array[];
}): ImageSet {
  const { size, reference } = frame;
  const scale = floorScale(reference);
  return {
    width: size,
    height: size,
    reference: floorPixels(reference, size, scale),
    referenceLabel: 'Lambert’s formula (exact)',
    images: STRATEGIES.map((s, i) => ({
      id: s,
      label: `${STRATEGY_LABEL[s]}, ${frame.spp} samples per pixel`,
      pixels: floorPixels(frame.images[i], size, scale),
      relMse: relMse(frame.images[i], reference),
    })),
    relMseOf: 'the radiance per pixel',
    fileStem: `area-light-floor-${frame.spp}spp`,
  };
}
