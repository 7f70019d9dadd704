/**
 * Points per second of the 2D sample sequences (fillSequence2D into a caller-owned Float64Array),
 * beside the plain xoshiro128** generator filling the same buffer. 2^18 points per iteration.
 * Run with `npx vitest bench bench/sequences.bench.ts --run` (or `npm run bench` for everything).
 */
import { bench, describe } from 'vitest';
import { fillSequence2D, Rng, SEQUENCE_KINDS } from '../src/core/random';

const N = 1 << 18;
const out = new Float64Array(2 * N);

describe(`2D sequences, ${N} points per iteration`, () => {
  for (const kind of SEQUENCE_KINDS) {
    bench(`${kind} (fillSequence2D)`, () => {
      fillSequence2D(kind, 7, N, out);
    });
  }
  bench('xoshiro128** Rng.fill (2 doubles per point)', () => {
    new Rng(7).fill(out);
  });
});
