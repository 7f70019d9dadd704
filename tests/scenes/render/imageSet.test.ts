/**
 * The render lab's measured pair: the reference's pixels are the exact values encoded as the canvas
 * encodes them, and where there is no exact value, the shown pixel itself (so that no error is
 * counted there).
 */
import { describe, expect, it } from 'vitest';
import { renderImageSet } from '../../../src/scenes/render/imageSet';
import { srgbByte } from '../../../src/core/image/srgb';

describe('renderImageSet', () => {
  it('encodes the exact reference, and copies the shown pixel where there is none', () => {
    // 2 × 2 pixels shown: 10, 200, 30, 40 (grey)
    const shown = new Uint8ClampedArray([10, 200, 30, 40].flatMap((v) => [v, v, v, 255]));
    const two = renderImageSet(shown, [0.25, NaN, 0, 1], 2, 8, 0.01, 'area');
    const b = srgbByte(0.25);
    expect(Array.from(two.reference)).toEqual([b, 200, 0, 255].flatMap((v) => [v, v, v, 255]));
    expect(two.images[0]).toMatchObject({ id: 'area', relMse: 0.01, pixels: shown });
    expect(two.fileStem).toBe('render-area-8spp');
  });
});
