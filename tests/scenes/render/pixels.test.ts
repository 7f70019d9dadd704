/** The render lab's pixel copy (sums → sRGB bytes), its image statistics and its description. */
import { describe, expect, it } from 'vitest';
import { copyMeans, copyPixels, imageStats, pixelMeans } from '../../../src/scenes/render/pixels';
import { srgbByte } from '../../../src/core/image/srgb';
import { describeImage, regionsOf } from '../../../src/scenes/render/describe';
import { defaultView, examScene, furnaceScene } from '../../../src/core/render/scene';

describe('pixel copy', () => {
  it('encodes linear radiance with the sRGB curve, clipped to [0, 1]', () => {
    expect(srgbByte(0)).toBe(0);
    expect(srgbByte(-3)).toBe(0);
    expect(srgbByte(1)).toBe(255);
    expect(srgbByte(7)).toBe(255);
    expect(srgbByte(0.0031308)).toBe(Math.round(255 * 12.92 * 0.0031308));
    expect(srgbByte(0.5)).toBe(188); // 1.055 · 0.5^(1/2.4) − 0.055 = 0.7354
  });

  it('writes each pixel’s mean as grey, black where no sample has arrived', () => {
    const sum = new Float64Array([2, 0.5, 9]);
    const count = new Uint32Array([2, 4, 0]);
    const rgba = new Uint8ClampedArray(12);
    copyPixels(sum, count, rgba);
    expect([...rgba]).toEqual([255, 255, 255, 255, ...Array(3).fill(srgbByte(0.125)), 255, 0, 0, 0, 255]);
  });

  it('reports the smallest count as spp and the mean of the means', () => {
    expect(imageStats(new Float64Array([2, 3]), new Uint32Array([2, 3]))).toEqual({ spp: 2, mean: 1 });
    const none = imageStats(new Float64Array([2, 0]), new Uint32Array([2, 0]));
    expect(none.spp).toBe(0);
    expect(none.mean).toBeNaN();
    const means = pixelMeans(new Float64Array([3, 1]), new Uint32Array([2, 0]));
    expect(means[0]).toBe(1.5);
    expect(means[1]).toBeNaN();
  });
});

describe('the image in words', () => {
  it('says what each ninth of the image shows', () => {
    const regions = regionsOf(examScene(), defaultView('exam'), 64);
    expect(regions[4][0]).toBe('sphere');
    expect(regions[7]).toEqual(['floor']);
    expect(regions.flat()).toContain('light');
    expect(regionsOf(furnaceScene(), defaultView('furnace'), 64)[0][0]).toBe('none');
  });

  it('gives the size, the mean brightness and the samples per pixel', () => {
    const t = describeImage(examScene(), regionsOf(examScene(), defaultView('exam'), 64), 64, {
      spp: 3,
      mean: 0.25,
    });
    expect(t).toMatch(/^A 64 × 64 image of the exam scene\. Top left: /);
    expect(t).toContain('middle centre: the textured sphere');
    expect(t).toContain('a light');
    expect(t).toContain('Mean brightness 0.25 (linear radiance) after 3 samples per pixel.');
    expect(
      describeImage(examScene(), regionsOf(examScene(), defaultView('exam'), 64), 64, { spp: 0, mean: NaN }),
    ).toContain('No sample has arrived yet.');
    const furnace = describeImage(furnaceScene(), regionsOf(furnaceScene(), defaultView('furnace'), 64), 64, {
      spp: 1,
      mean: 1,
    });
    expect(furnace).toContain('middle centre: the sphere;');
  });

  it('draws an image of means as it draws the sums they come from, a missing pixel black', () => {
    const sum = Float64Array.of(0.3, 4, 0, 0.9);
    const count = Uint32Array.of(1, 8, 0, 3);
    const a = new Uint8ClampedArray(16);
    const b = new Uint8ClampedArray(16);
    copyPixels(sum, count, a);
    copyMeans(pixelMeans(sum, count), b);
    expect(Array.from(b)).toEqual(Array.from(a));
    expect(b[8]).toBe(0);
  });
});
