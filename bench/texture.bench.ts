/**
 * Texture lookups per second: the allocation-free reconstruction kernel (reconstructInto, writing
 * a caller-owned Float64Array) beside the same lookups through the stencil-returning functions
 * (one object per lookup, what the scene uses for a single query), for both conventions; and
 * spherical (u, v) of random points. Run with `npx vitest bench bench/texture.bench.ts --run`.
 */
import { bench, describe } from 'vitest';
import { Rng } from '../src/core/random';
import {
  bilinearStencil,
  randomGrid,
  reconstructInto,
  sphericalUV,
  type LookupOptions,
} from '../src/core/texture';

const W = 256;
const grid = randomGrid(64, 64, 1);
const out = new Float64Array(W * W);
const corner: LookupOptions = { align: 'corner', vflip: false, wrap: 'clamp' };
const center: LookupOptions = { align: 'center', vflip: false, wrap: 'repeat' };

describe(`texture reconstruction, 64 × 64 grid, ${W * W} points per iteration`, () => {
  bench('bilinear, batched kernel (corner nodes, clamp)', () => {
    reconstructInto(grid, corner, 'bilinear', W, W, out);
  });
  bench('bilinear, batched kernel (texel centres, repeat)', () => {
    reconstructInto(grid, center, 'bilinear', W, W, out);
  });
  bench('nearest, batched kernel (corner nodes)', () => {
    reconstructInto(grid, corner, 'nearest', W, W, out);
  });
  bench('bilinear via bilinearStencil (object per lookup)', () => {
    for (let py = 0; py < W; py++)
      for (let px = 0; px < W; px++)
        out[py * W + px] = bilinearStencil(grid, (px + 0.5) / W, 1 - (py + 0.5) / W, corner).value;
  });
});

const N = 100_000;
const pts = new Rng(2).fill(new Float64Array(3 * N));
for (let k = 0; k < pts.length; k++) pts[k] = 2 * pts[k] - 1;

describe(`spherical (u, v), ${N} points per iteration`, () => {
  bench('sphericalUV', () => {
    let s = 0;
    for (let i = 0; i < N; i++) {
      const r = sphericalUV(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]);
      if (r.ok) s += r.u + r.v;
    }
    if (s < 0) throw new Error('unreachable');
  });
});
