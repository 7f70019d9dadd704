/**
 * Ray–sphere intersections per second on 10⁶ random rays: the batched kernel
 * (intersectRaySphereBatch, Float64Array in, caller-owned Float64Array out, no allocation), robust
 * and textbook, beside the per-object path the page uses for one ray (intersectRaySphere: tuples
 * in, a result object out). Run with `npx vitest bench bench/raySphere.bench.ts --run`.
 */
import { bench, describe } from 'vitest';
import { Rng } from '../src/core/random';
import { intersectRaySphere, intersectRaySphereBatch, RAY_STRIDE, type Vec3 } from '../src/core/geometry';

const N = 1_000_000;
const rays = new Rng(5).fill(new Float64Array(N * RAY_STRIDE));
for (let k = 0; k < rays.length; k++) rays[k] = 8 * rays[k] - 4; // origins and directions in [−4, 4)³
const out = new Float64Array(N);
const C: Vec3 = [0.25, -0.5, 0.125];
const R = 1.5;

describe(`ray–sphere, ${N} rays per iteration`, () => {
  bench('batched kernel, robust (RTG ch. 7)', () => {
    intersectRaySphereBatch(rays, N, C[0], C[1], C[2], R, 'stable', out);
  });
  bench('batched kernel, textbook', () => {
    intersectRaySphereBatch(rays, N, C[0], C[1], C[2], R, 'naive', out);
  });
  bench('per-object intersectRaySphere (robust, object per ray)', () => {
    for (let i = 0, j = 0; i < N; i++, j += RAY_STRIDE) {
      const res = intersectRaySphere(
        [rays[j], rays[j + 1], rays[j + 2]],
        [rays[j + 3], rays[j + 4], rays[j + 5]],
        C,
        R,
        'stable',
      );
      out[i] = res.ok && res.tHit !== null ? res.tHit : Infinity;
    }
  });
});
