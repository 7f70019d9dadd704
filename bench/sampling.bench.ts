/**
 * Samples per second of hemisphere warps: the batched exam-lobe kernel (unit vectors into a
 * caller-owned Float64Array) beside a naive per-object version written the way the key writes the
 * formulas (θ = ½ arccos(1 − 2ξ₁), φ = ln((e^{2π} − 1)ξ₂ + 1), one {x, y, z} object per sample),
 * and the other batched warps. Run with `npx vitest bench bench/sampling.bench.ts --run`.
 */
import { bench, describe } from 'vitest';
import { Rng } from '../src/core/random';
import {
  sampleCosineHemisphereBatch,
  sampleExamLobeBatch,
  samplePhongLobeBatch,
  sampleUniformHemisphereBatch,
} from '../src/core/sampling';

const N = 1_000_000;
const u = new Rng(1).fill(new Float64Array(2 * N));
const out = new Float64Array(3 * N);
const C = Math.exp(2 * Math.PI) - 1;

function naiveExam(n: number): { x: number; y: number; z: number }[] {
  const res: { x: number; y: number; z: number }[] = [];
  for (let i = 0; i < n; i++) {
    const theta = 0.5 * Math.acos(1 - 2 * u[2 * i]);
    const phi = Math.log(C * u[2 * i + 1] + 1);
    res.push({ x: Math.sin(theta) * Math.cos(phi), y: Math.sin(theta) * Math.sin(phi), z: Math.cos(theta) });
  }
  return res;
}

describe(`hemisphere warps, ${N.toExponential()} samples per iteration`, () => {
  bench('exam lobe, batched kernel (Float64Array out)', () => {
    sampleExamLobeBatch(u, out, N);
  });
  bench('exam lobe, naive (object per sample, key formulas)', () => {
    naiveExam(N);
  });
  bench('uniform hemisphere, batched', () => {
    sampleUniformHemisphereBatch(u, out, N);
  });
  bench('cosine hemisphere (concentric), batched', () => {
    sampleCosineHemisphereBatch(u, out, N);
  });
  bench('Phong n = 8, batched', () => {
    samplePhongLobeBatch(u, out, N, 8);
  });
});
