/**
 * Cost of the χ² machinery behind the "run the χ² test" buttons: hemisphereChi2 on 1e6 cosine-
 * distributed directions (binning + expected counts by adaptive quadrature, 10 × 20 bins), the
 * expected counts alone, and chi2UpperTail. Run with `npx vitest bench bench/verify.bench.ts --run`.
 */
import { bench, describe } from 'vitest';
import { Rng } from '../src/core/random';
import { chi2UpperTail, hemisphereChi2 } from '../src/core/verify';

const N = 1_000_000;
const rng = new Rng(5);
const dirs = new Float64Array(3 * N);
for (let i = 0; i < N; i++) {
  const r = Math.sqrt(rng.nextFloat());
  const phi = 2 * Math.PI * rng.nextFloat();
  dirs[3 * i] = r * Math.cos(phi);
  dirs[3 * i + 1] = r * Math.sin(phi);
  dirs[3 * i + 2] = Math.sqrt(Math.max(0, 1 - r * r));
}
const cosinePdf = (_x: number, _y: number, z: number) => (z > 0 ? z / Math.PI : 0);
const one = new Float64Array([0, 0, 1]);
let sink = 0;

describe(`hemisphere χ², 1000000 samples per iteration`, () => {
  bench('hemisphereChi2 (binning + expected counts + test)', () => {
    sink += hemisphereChi2(dirs, N, cosinePdf).statistic;
  });
});

describe('χ² pieces, per call', () => {
  bench('expected counts only (10 × 20 bins, adaptive Gauss–Legendre)', () => {
    sink += hemisphereChi2(one, 1, cosinePdf).expected[0];
  });
  bench('chi2UpperTail(250, 199)', () => {
    sink += chi2UpperTail(250, 199);
  });
});

export { sink };
