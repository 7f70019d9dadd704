/**
 * The render lab's image and its reference as the measuring panel takes them (ui/imageMeasure): the
 * 8-bit sRGB pixels the canvas shows, and the exact reference encoded the same way (core/image/srgb).
 * Where a pixel has no exact reference (NaN: a shadowed or glossy point, a silhouette, more than one
 * bounce), the reference takes the render's own pixel, so that FLIP and the downloaded PNGs count
 * no error there: only pixels with a closed form can differ.
 */
import { srgbByte } from '../../core/image/srgb';
import type { ImageSet } from '../../ui/imageMeasure';

export function renderImageSet(
  shown: Uint8ClampedArray,
  reference: ArrayLike<number>,
  res: number,
  spp: number,
  relMse: number,
  strategy: string,
): ImageSet {
  const ref = new Uint8ClampedArray(4 * res * res);
  for (let k = 0; k < res * res; k++) {
    const o = 4 * k;
    if (Number.isFinite(reference[k])) ref[o] = ref[o + 1] = ref[o + 2] = srgbByte(reference[k]);
    else {
      ref[o] = shown[o];
      ref[o + 1] = shown[o + 1];
      ref[o + 2] = shown[o + 2];
    }
    ref[o + 3] = 255;
  }
  return {
    width: res,
    height: res,
    reference: ref,
    referenceLabel: 'exact where a closed form exists; elsewhere the render’s own pixel',
    images: [{ id: strategy, label: `${strategy}, ${spp} samples per pixel`, pixels: shown, relMse }],
    relMseOf: 'the radiance of the pixels with a closed form',
    fileStem: `render-${strategy}-${spp}spp`,
  };
}
