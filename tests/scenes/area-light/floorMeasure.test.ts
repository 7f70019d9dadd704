/**
 * The FLIP the area-light page shows is the FLIP of the PNGs it lets you download: the shown mean
 * (the worker task, on the pixels the canvases paint) equals the mean computed as scripts/flip.mjs
 * computes it from the encoded and decoded PNG files.
 */
import { describe, expect, it } from 'vitest';
import { renderJob } from '../../../src/scenes/area-light/jobs';
import { buildModel } from '../../../src/scenes/area-light/model';
import { floorJob } from '../../../src/scenes/area-light/floor';
import { floorImageSet, floorPixels, floorScale } from '../../../src/scenes/area-light/floorPixels';
import { defaultValues } from '../../../src/kit/params';
import { schema } from '../../../src/scenes/area-light/params';
import { flipTask } from '../../../src/workers/flipJobs';
import { decodePng, encodePng, rgbFromRgba8 } from '../../../src/core/image/png';
import { flipErrorMap } from '../../../src/core/image/flip';
import { poolError } from '../../../src/core/image/pooling';
import { relMse } from '../../../src/core/image/relMse';

describe('floor pixels', () => {
  it('map radiance to warm-white gamma-2.2 bytes, NaN to the hatch colour', () => {
    const px = floorPixels([2, 2 * 0.5 ** 2.2, 0, NaN, 5], 1, 2);
    expect([...px.slice(0, 4)]).toEqual([255, 240, 205, 255]);
    expect(floorPixels([2 * 0.5 ** 2.2], 1, 2)[0]).toBe(128); // 255 · 0.5 = 127.5 rounds up
    expect([...floorPixels([0], 1, 2)]).toEqual([0, 0, 0, 255]);
    expect([...floorPixels([NaN], 1, 2)]).toEqual([120, 60, 120, 255]);
    expect([...floorPixels([5], 1, 2)]).toEqual([255, 240, 205, 255]); // clamped
    expect(floorScale([NaN, 0.5, 3, Infinity])).toBe(3);
    expect(floorScale([0, NaN])).toBe(1);
  });
});

describe('the measured floor images', async () => {
  const job = floorJob(buildModel(defaultValues(schema)), 3, 24);
  const frame = await renderJob(job);
  const set = floorImageSet(frame);
  const png = (data: Uint8ClampedArray) =>
    decodePng(encodePng({ width: set.width, height: set.height, data }));

  it('measure every strategy with relMSE of the radiance', () => {
    expect(set.images.map((im) => im.id)).toEqual(['area', 'solid-angle', 'cosine']);
    set.images.forEach((im, i) => expect(im.relMse).toBe(relMse(frame.images[i], frame.reference)));
    expect(set.images.every((im) => im.relMse > 0)).toBe(true);
  });

  it('show the FLIP mean of the PNGs one downloads, and download the error map shown', async () => {
    const ref = png(set.reference);
    for (const im of set.images) {
      const shown = await flipTask({
        width: set.width,
        height: set.height,
        reference: set.reference,
        test: im.pixels,
      });
      const test = png(im.pixels);
      expect([...test.data]).toEqual([...im.pixels]);
      const map = flipErrorMap(rgbFromRgba8(ref), rgbFromRgba8(test));
      expect(shown.mean).toBe(poolError(map).mean);
      expect(shown.weightedMedian).toBe(poolError(map).weightedMedian);
      expect(shown.mean).toBeGreaterThan(0);
      expect([...png(shown.errorMap).data]).toEqual([...shown.errorMap]);
    }
  });
});
