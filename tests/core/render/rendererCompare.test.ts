/**
 * The comparison of two renderers' images within their noise: images of the same estimator pass,
 * a biased image (too bright by a few per cent, or no-cos-l area sampling) fails, noiseless pixels
 * agree to float32 rounding or fail, and pixels far below the image's scale are not differences.
 */
import { describe, expect, it } from 'vitest';
import { compareRenderers, momentsFromSums, COMPARE_ALPHA } from '../../../src/core/render/rendererCompare';
import { makeCpuRenderer, renderImage } from '../../../src/core/render/cpuRenderer';
import { renderMoments } from '../../../src/core/render/moments';
import { defaultView, examScene, furnaceScene } from '../../../src/core/render/scene';
import { Rng } from '../../../src/core/random/rng';

/** An image of `pixels` pixels whose samples are exponential with mean mu[k] (skewed, like a light hit). */
function skewed(mu: (k: number) => number, pixels: number, n: number, seed: number) {
  const rng = new Rng(seed, 0);
  const sum = new Float64Array(pixels);
  const sq = new Float64Array(pixels);
  for (let k = 0; k < pixels; k++)
    for (let s = 0; s < n; s++) {
      const x = -mu(k) * Math.log(1 - rng.nextFloat());
      sum[k] += x;
      sq[k] += x * x;
    }
  return momentsFromSums(sum, sq, n);
}

describe('compareRenderers', () => {
  it('passes two images of one skewed estimator, for many seeds', () => {
    const mu = (k: number) => 0.1 + (k % 17) / 20;
    let fails = 0;
    for (let seed = 1; seed <= 40; seed++) {
      const r = compareRenderers(skewed(mu, 1024, 16, seed), skewed(mu, 1024, 16, 1000 + seed));
      expect(r.noisy).toBe(1024);
      if (!r.pass) fails++;
    }
    expect(fails).toBeLessThanOrEqual(1);
  });

  it('fails an image 5 % too bright', () => {
    const mu = (k: number) => 0.1 + (k % 17) / 20;
    const r = compareRenderers(
      skewed((k) => 1.05 * mu(k), 1024, 16, 3),
      skewed(mu, 1024, 16, 4),
    );
    expect(r.pass).toBe(false);
    expect(r.p).toBeLessThan(COMPARE_ALPHA);
    expect(r.t).toBeGreaterThan(0);
  });

  it('holds noiseless pixels to float32 rounding, relative to the pixel or the image', () => {
    const one = { mean: Float64Array.of(1, 1, 1e-30), se2: new Float64Array(3) };
    const near = { mean: Float64Array.of(Math.fround(1 + 2 ** -22), 1, 0), se2: new Float64Array(3) };
    const r = compareRenderers(near, one);
    expect(r).toMatchObject({ quiet: 3, noisy: 0, quietMismatches: 0, pass: true, p: 1 });
    const off = { mean: Float64Array.of(1.001, 1, 0), se2: new Float64Array(3) };
    const bad = compareRenderers(off, one);
    expect(bad.quietMismatches).toBe(1);
    expect(bad.pass).toBe(false);
  });

  it('leaves out pixels that are not finite and refuses images of different sizes', () => {
    const a = { mean: Float64Array.of(NaN, 1), se2: Float64Array.of(0, 0) };
    const r = compareRenderers(a, { mean: Float64Array.of(1, 1), se2: Float64Array.of(0, 0) });
    expect(Number.isNaN(r.z[0])).toBe(true);
    expect(r.quiet).toBe(1);
    expect(() => compareRenderers(a, { mean: new Float64Array(3), se2: new Float64Array(3) })).toThrow(
      RangeError,
    );
  });

  it('on the core renderer: two seeds of mis-power agree; area sampling without cos θ_l does not', () => {
    const scene = examScene();
    const view = defaultView('exam');
    const run = (strategy: 'mis-power' | 'area', seed: number, bias: 'none' | 'no-cos-l' = 'none') =>
      renderMoments(makeCpuRenderer(scene, view, 24, 24, { strategy, bounces: 1, bias }, seed), 24, 24, 16);
    expect(compareRenderers(run('mis-power', 1), run('mis-power', 2)).pass).toBe(true);
    const biased = compareRenderers(run('area', 3, 'no-cos-l'), run('area', 4));
    expect(biased.pass).toBe(false);
    expect(biased.t).toBeGreaterThan(0);
  });

  it('the CPU side draws the progressive render’s own samples: its means are the image’s', () => {
    const make = () =>
      makeCpuRenderer(examScene(), defaultView('exam'), 12, 12, { strategy: 'mis-power', bounces: 2 }, 9);
    const m = renderMoments(make(), 12, 12, 6);
    const img = renderImage(make(), 12, 12, 6, 1);
    m.mean.forEach((x, k) => expect(x).toBeCloseTo(img[k], 12));
    expect(m.se2.some((v) => v > 0)).toBe(true);
  });

  it('on the furnace under cosine sampling every pixel is 1 without noise', () => {
    const m = renderMoments(
      makeCpuRenderer(furnaceScene(), defaultView('furnace'), 16, 16, { strategy: 'cosine', bounces: 3 }, 5),
      16,
      16,
      8,
    );
    for (const x of m.mean) expect(Math.abs(x - 1)).toBeLessThan(1e-14);
    const r = compareRenderers(m, m);
    expect(r).toMatchObject({ noisy: 0, quiet: 256, pass: true });
  });
});
