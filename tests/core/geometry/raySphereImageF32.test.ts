// The float32 image of the GPU panel: one ray per pixel, emulated float32 against a float64
// reference of the same rays.
import { describe, expect, it } from 'vitest';
import {
  countHitMismatch,
  countUlpMismatch,
  intersectRaySphereF32,
  renderSphereF32,
  renderSphereReference,
  sphereImageSetup,
  ulpErrors,
} from '../../../src/core/geometry';

describe('float32 sphere image', () => {
  it('each pixel is the full float32 intersection of its ray', () => {
    const s = sphereImageSetup(300, 16, 16);
    const img = renderSphereF32(s);
    for (let i = 0; i < 256; i++) {
      const d = [s.dirs[3 * i], s.dirs[3 * i + 1], s.dirs[3 * i + 2]] as const;
      for (const m of ['naive', 'stable'] as const) {
        const h = intersectRaySphereF32([0, 0, 0], d, s.centre, s.r, m);
        if (!h.ok) throw new Error(h.message);
        expect(img[m][i]).toBe(h.tHit ?? Infinity);
      }
    }
  });

  it('close by both tests are right; at 10⁴ r the textbook one is wrong on thousands of pixels', () => {
    const near = sphereImageSetup(10, 96, 96);
    const ref = renderSphereReference(near);
    const e = renderSphereF32(near);
    expect(countHitMismatch(e.naive, ref)).toBe(0);
    expect(countHitMismatch(e.stable, ref)).toBe(0);
    const far = sphereImageSetup(1e4, 96, 96);
    const ref4 = renderSphereReference(far);
    const e4 = renderSphereF32(far);
    expect(countHitMismatch(e4.naive, ref4)).toBeGreaterThan(1000);
    expect(countHitMismatch(e4.stable, ref4)).toBe(0);
    const errs = ulpErrors(e4.stable, ref4, new Float32Array(96 * 96));
    expect(Math.max(...errs)).toBeLessThan(8);
  });

  it('the mismatch counter counts ulps and lost hits', () => {
    const a = Float32Array.from([1, 1, Infinity, 2]);
    const b = Float32Array.from([1, Math.fround(1 + 3 * 2 ** -23), 1, 2]);
    expect(countUlpMismatch(a, b, 2)).toBe(2);
    expect(countUlpMismatch(a, b, 3)).toBe(1);
  });
});
