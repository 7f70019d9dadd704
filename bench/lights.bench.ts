/**
 * Throughput of the area-light kernels (samples per second): the batched estimator kernel for each
 * strategy beside a naive per-sample version that allocates an object per sample, plus the solid
 * angle and Lambert's formula per call. Run: npx vitest bench --run bench/lights.bench.ts
 */
import { bench, describe } from 'vitest';
import { Rng } from '../src/core/random';
import {
  areaLightTerms,
  lambertianFloorRadiance,
  makeRectLight,
  makeSphericalRect,
  rectSolidAngle,
  sampleSphericalRectangle,
  type AreaLightSetup,
} from '../src/core/lights';

const N = 100_000;
const light = makeRectLight([0.3, 0.2, 2], 1.5, 1, 20);
const setup: AreaLightSetup = { light, occluder: null, px: 0, py: 0, pz: 0, L: 1, rho: 0.8 };
const u = new Rng(1).fill(new Float64Array(2 * N));
const terms = new Float64Array(N);

describe(`area-light estimator kernels, ${N} samples per iteration`, () => {
  bench('area (batched)', () => areaLightTerms(setup, 'area', u, N, terms));
  bench('solid-angle (batched)', () => areaLightTerms(setup, 'solid-angle', u, N, terms));
  bench('cosine (batched)', () => areaLightTerms(setup, 'cosine', u, N, terms));
  bench('solid-angle (naive: a point object and a fresh setup per sample)', () => {
    let s = 0;
    for (let i = 0; i < N; i++) {
      const q = makeSphericalRect(light, 0, 0, 0);
      const pt = { x: 0, y: 0, z: 0 };
      const out = [0, 0, 0];
      sampleSphericalRectangle(q, u[2 * i], u[2 * i + 1], out);
      pt.x = out[0];
      pt.y = out[1];
      pt.z = out[2];
      s += pt.z / Math.hypot(pt.x, pt.y, pt.z);
    }
    terms[0] = s;
  });
});

describe('closed forms, per call', () => {
  bench('rectangle solid angle (Van Oosterom–Strackee)', () => {
    terms[1] = rectSolidAngle(light, 0.1, 0.2, 0);
  });
  bench("Lambert's formula (clipped)", () => {
    terms[2] = lambertianFloorRadiance(light, 0.1, 0.2, 0, 1, 0.8);
  });
});
