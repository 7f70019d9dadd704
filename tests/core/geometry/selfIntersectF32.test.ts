// Shadow acne in float32: self-hits of shadow rays from float32 hit points on the lit side of a
// sphere, against the offset ε, at several distances, and pbrt's error-bound offset.
import { describe, expect, it } from 'vitest';
import {
  acneSweepF32,
  gammaF32,
  pbrtOffsetF32,
  shadowAcneF32,
  sphereImageSetup,
  U32,
} from '../../../src/core/geometry';

const n = Math.hypot(-1, 0.8, 0.6);
const LIGHT = [-1 / n, 0.8 / n, 0.6 / n] as const;

describe('shadow acne in float32', () => {
  it('γₙ is n u₃₂ to first order', () => {
    expect(gammaF32(5) / (5 * U32)).toBeCloseTo(1, 6);
  });

  it.each([10, 100, 1e3, 1e4])('D/r = %d: many self-hits at ε = 0, none with pbrt’s offset', (D) => {
    const s = sphereImageSetup(D, 64, 64);
    const none = shadowAcneF32(s, LIGHT, 0);
    expect(none.lit).toBeGreaterThan(500);
    expect(none.selfHits / none.lit).toBeGreaterThan(0.1);
    const pb = shadowAcneF32(s, LIGHT, 'pbrt');
    expect(pb.lit).toBeGreaterThan(500);
    expect(pb.selfHits).toBe(0);
    // pbrt's offset is a few u₃₂ times the hit point's size (≈ D)
    expect(pb.maxPbrtOffset).toBeGreaterThan(U32 * D);
    expect(pb.maxPbrtOffset).toBeLessThan(40 * U32 * (D + 1));
  });

  it('the ε needed grows like D (a float32 coordinate of size D is spaced u₃₂·D)', () => {
    const need = [10, 1e2, 1e3, 1e4].map(
      (D) => acneSweepF32(sphereImageSetup(D, 48, 48), D, LIGHT).epsNeeded!,
    );
    for (const e of need) expect(e).not.toBeNull();
    for (let i = 1; i < need.length; i++) {
      expect(need[i] / need[i - 1]).toBeGreaterThan(3);
      expect(need[i] / need[i - 1]).toBeLessThan(40);
    }
    // the fixed ε = 10⁻⁴ r that works in double (the page's t_min) fails in float32 at 10⁴ r
    const far = shadowAcneF32(sphereImageSetup(1e4, 48, 48), LIGHT, 1e-4);
    expect(far.selfHits).toBeGreaterThan(0);
  });

  it('the pbrt offset point lies outside the sphere', () => {
    const c = [Math.fround(6000), Math.fround(1800), Math.fround(1200)] as const;
    const p = [Math.fround(5999.2), Math.fround(1800.3), Math.fround(1200.1)] as const;
    const q = pbrtOffsetF32(p, c, 1);
    const d = Math.hypot(q.origin[0] - c[0], q.origin[1] - c[1], q.origin[2] - c[2]);
    expect(d).toBeGreaterThan(1);
  });
});
