/**
 * The first two dimensions of the Sobol' sequence with Owen scrambling and Burley's hash-based
 * index shuffle. Dimension 0 is the van der Corput sequence (generator matrix = identity);
 * dimension 1 uses the Joe–Kuo direction numbers for s = 1, a = 0, m₁ = 1, i.e. v_k = v_{k−1} ⊕
 * (v_{k−1} ≫ 1) (Pascal's triangle mod 2). Together they form a (0, 2)-sequence in base 2: every
 * aligned block of 2^m points has exactly one point in each elementary interval of area 2^-m.
 * Source: Sobol' (1967); Joe & Kuo (2008) "Constructing Sobol sequences with better two-dimensional
 * projections" (new-joe-kuo-6.21201); Burley (2020) JCGT 9(4); pbrt-v4 §8.7.
 */
import { owenHashReversedI, reverseBits32I } from './owen';

/** Direction numbers of Sobol' dimension 1, left-aligned in 32 bits. */
export const SOBOL_DIM1 = (() => {
  const v = new Uint32Array(32);
  v[0] = 0x80000000;
  for (let k = 1; k < 32; k++) v[k] = (v[k - 1] ^ (v[k - 1] >>> 1)) >>> 0;
  return v;
})();

/** Unscrambled Sobol' dimension 0 of index i (uint32): the bits of i reversed, as a uint32 fraction. */
export function sobolDim0Bits(i: number): number {
  return reverseBits32I(i) >>> 0;
}

/**
 * Byte tables for dimension 1: SOBOL_DIM1_BYTES[256·b + v] = XOR of the direction numbers selected by the
 * bits of byte value v at byte position b, so a point needs 4 lookups instead of a 32-step loop.
 */
export const SOBOL_DIM1_BYTES = (() => {
  const t = new Int32Array(1024);
  for (let b = 0; b < 4; b++) {
    for (let v = 0; v < 256; v++) {
      let x = 0;
      for (let k = 0; k < 8; k++) if (v & (1 << k)) x ^= SOBOL_DIM1[8 * b + k];
      t[256 * b + v] = x;
    }
  }
  return t;
})();

/** Unscrambled Sobol' dimension 1 of index i (any 32-bit word), int32 result. */
export function sobolDim1I(i: number): number {
  return (
    SOBOL_DIM1_BYTES[i & 255] ^
    SOBOL_DIM1_BYTES[256 + ((i >>> 8) & 255)] ^
    SOBOL_DIM1_BYTES[512 + ((i >>> 16) & 255)] ^
    SOBOL_DIM1_BYTES[768 + (i >>> 24)]
  );
}

/** Unscrambled Sobol' dimension 1 of index i (uint32), as a uint32 fraction (× 2^-32). */
export function sobolDim1Bits(i: number): number {
  return sobolDim1I(i) >>> 0;
}

/**
 * Owen-scrambled, index-shuffled Sobol' point i, dimension 0 and 1, as uint32 fractions. The index
 * is itself Owen-scrambled (Burley 2020 §4), which maps the first 2^m indices onto an aligned block
 * of 2^m points, so every power-of-two prefix is still a (0, m, 2)-net.
 * Domain: i integer in [0, 2^32); seeds uint32. Writes the two uint32 values into out[0], out[1].
 */
export function shuffledSobol2Bits(
  i: number,
  shuffleSeed: number,
  seed0: number,
  seed1: number,
  out: Uint32Array,
): void {
  // owen(v) = rev(hash(rev(v))); the reversals of dimension 0 (rev of the index) cancel
  const j = reverseBits32I(owenHashReversedI(reverseBits32I(i), shuffleSeed | 0));
  out[0] = reverseBits32I(owenHashReversedI(j, seed0 | 0)) >>> 0;
  out[1] = reverseBits32I(owenHashReversedI(reverseBits32I(sobolDim1I(j)), seed1 | 0)) >>> 0;
}
