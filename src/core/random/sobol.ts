/**
 * The first two dimensions of the Sobol' sequence with Owen scrambling and Burley's hash-based
 * index shuffle. Dimension 0 is the van der Corput sequence (generator matrix = identity);
 * dimension 1 uses the Joe–Kuo direction numbers for s = 1, a = 0, m₁ = 1, i.e. v_k = v_{k−1} ⊕
 * (v_{k−1} ≫ 1) (Pascal's triangle mod 2). Together they form a (0, 2)-sequence in base 2: every
 * aligned block of 2^m points has exactly one point in each elementary interval of area 2^-m.
 * Source: Sobol' (1967); Joe & Kuo (2008) "Constructing Sobol sequences with better two-dimensional
 * projections" (new-joe-kuo-6.21201); Burley (2020) JCGT 9(4); pbrt-v4 §8.7.
 */
import { owenScramble32, reverseBits32 } from './owen';

/** Direction numbers of Sobol' dimension 1, left-aligned in 32 bits. */
export const SOBOL_DIM1 = (() => {
  const v = new Uint32Array(32);
  v[0] = 0x80000000;
  for (let k = 1; k < 32; k++) v[k] = (v[k - 1]! ^ (v[k - 1]! >>> 1)) >>> 0;
  return v;
})();

/** Unscrambled Sobol' dimension 0 of index i (uint32): the bits of i reversed, as a uint32 fraction. */
export function sobolDim0Bits(i: number): number {
  return reverseBits32(i >>> 0);
}

/** Unscrambled Sobol' dimension 1 of index i (uint32), as a uint32 fraction (× 2^-32). */
export function sobolDim1Bits(i: number): number {
  let x = 0;
  let k = 0;
  let a = i >>> 0;
  while (a !== 0) {
    if (a & 1) x ^= SOBOL_DIM1[k]!;
    a >>>= 1;
    k++;
  }
  return x >>> 0;
}

/**
 * Owen-scrambled, index-shuffled Sobol' point i, dimension 0 and 1, as uint32 fractions. The index
 * is itself Owen-scrambled (Burley 2020 §4), which maps the first 2^m indices onto an aligned block
 * of 2^m points, so every power-of-two prefix is still a (0, m, 2)-net.
 * Domain: i integer in [0, 2^32); seeds uint32. Writes the two uint32 values into out[0], out[1].
 */
export function shuffledSobol2Bits(i: number, shuffleSeed: number, seed0: number, seed1: number, out: Uint32Array): void {
  const j = owenScramble32(i >>> 0, shuffleSeed);
  out[0] = owenScramble32(sobolDim0Bits(j), seed0);
  out[1] = owenScramble32(sobolDim1Bits(j), seed1);
}
