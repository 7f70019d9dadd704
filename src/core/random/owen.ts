/**
 * Bit-level helpers for scrambled low-discrepancy sequences: 32-bit reversal, hash-based Owen
 * scrambling in base 2, Owen-scrambled radical inverse in base 3, and counter-based uniform
 * hashing. All integer arithmetic is 32-bit (Math.imul), identical on every engine.
 *
 * Internally values are kept as signed int32 (the `…I` functions) so optimizing JS engines keep
 * them in registers; the exported uint32 forms convert with `>>> 0` only at the boundary.
 */
import { ONE_MINUS_EPS as ONE_MINUS_EPS_RNG, TWO_POW_M53 as TWO_POW_M53_RNG } from './rng';

// Local copies (see the note on local aliases in sequences.ts: imported bindings are slow in
// hot loops under Vite's module runner).
const ONE_MINUS_EPS = ONE_MINUS_EPS_RNG;
const TWO_POW_M53 = TWO_POW_M53_RNG;

/** 2^-32: converts a uint32 to a double in [0, 1). */
export const TWO_POW_M32 = 1 / 4294967296;

/**
 * 32-bit avalanche hash ("lowbias32", C. Wellons 2018, hash-prospector), int32 in and out.
 * Bijective on 32-bit words.
 */
export function hash32I(x: number): number {
  x ^= x >>> 16;
  x = Math.imul(x, 0x7feb352d);
  x ^= x >>> 15;
  x = Math.imul(x, 0x846ca68b);
  return x ^ (x >>> 16);
}

/** Reverse the 32 bits of a 32-bit word; int32 result (see {@link reverseBits32}). */
export function reverseBits32I(v: number): number {
  v = ((v >>> 1) & 0x55555555) | ((v & 0x55555555) << 1);
  v = ((v >>> 2) & 0x33333333) | ((v & 0x33333333) << 2);
  v = ((v >>> 4) & 0x0f0f0f0f) | ((v & 0x0f0f0f0f) << 4);
  v = ((v >>> 8) & 0x00ff00ff) | ((v & 0x00ff00ff) << 8);
  return (v >>> 16) | (v << 16);
}

/** Reverse the 32 bits of a uint32 (bit 0 ↔ bit 31). Domain: any uint32; returns a uint32. */
export function reverseBits32(v: number): number {
  return reverseBits32I(v) >>> 0;
}

/**
 * The hashing core of {@link owenScramble32}, applied to an already bit-reversed word: every step
 * lets only lower bits affect higher ones (addition, multiplication by even constants, odd
 * multipliers), so bit k is flipped by a function of bits 0 … k−1. int32 in and out.
 */
export function owenHashReversedI(v: number, seed: number): number {
  v ^= Math.imul(v, 0x3d20adea);
  v = (v + seed) | 0;
  v = Math.imul(v, (seed >>> 16) | 1);
  v ^= Math.imul(v, 0x05526c56);
  v ^= Math.imul(v, 0x53a22864);
  return v;
}

/**
 * Hash-based nested uniform (Owen) scrambling of a 32-bit binary fraction v·2^-32: each bit is
 * flipped by a pseudo-random function of the bits above it, so intervals [k/2^m, (k+1)/2^m) map to
 * such intervals (stratification is preserved) while the set is randomized.
 * Domain: v and seed any uint32; returns a uint32. Bijective in v for each seed.
 * Source: Burley 2020, "Practical Hash-based Owen Scrambling" (JCGT 9(4)), with the improved
 * constants of pbrt-v4 `FastOwenScrambler` (util/lowdiscrepancy.h, after N. Vegdahl).
 */
export function owenScramble32(v: number, seed: number): number {
  return reverseBits32I(owenHashReversedI(reverseBits32I(v), seed | 0)) >>> 0;
}

/** Combine two 32-bit hashes (order matters). Returns a uint32. */
export function hashCombine(a: number, b: number): number {
  return hash32I(a ^ Math.imul(hash32I(b), 0x9e3779b1)) >>> 0;
}

/** POW3_INV[j] = 3^-(j+1), exact to rounding (3^k is exact in a double for k ≤ 33). */
const POW3_INV = (() => {
  const t = new Float64Array(35);
  let p = 1;
  for (let j = 0; j < 35; j++) {
    p *= 3;
    t[j] = 1 / p;
  }
  return t;
})();

// The six permutations of {0, 1, 2}, flattened.
const PERM3 = new Uint8Array([0, 1, 2, 0, 2, 1, 1, 0, 2, 1, 2, 0, 2, 0, 1, 2, 1, 0]);

/**
 * Owen-scrambled radical inverse in base 3 of a non-negative integer index: digit j of the index
 * (least significant first) becomes digit j after the ternary point, permuted by one of the six
 * permutations of {0,1,2} chosen by a hash of `seed` and the digits before it (nested scrambling).
 * Leading zero digits are permuted too, so the result is uniform on [0, 1) to full precision.
 * Domain: index integer in [0, 2^53), seed any 32-bit value; returns a double in [0, 1).
 * Source: pbrt-v4 `OwenScrambledRadicalInverse` (util/lowdiscrepancy.h), Owen (1995).
 */
export function owenRadicalInverse3(index: number, seed: number): number {
  let a = index;
  let h = hash32I(seed | 0);
  let x = 0;
  let j = 0;
  // Scramble the first 20 digits (3^20 > 2^32, enough for every point count we support, so any
  // prefix of up to 3^20 points keeps its stratification) and more if the index has more digits.
  // Below that, the nested scramble of the remaining zero digits is a uniform offset in the
  // remaining interval of width 3^-j: draw it from the hash (same distribution, fewer steps).
  while ((a > 0 || j < 20) && j < 34) {
    const next = a < 2147483648 ? (a / 3) | 0 : Math.floor(a / 3);
    const digit = a - 3 * next;
    x += PERM3[3 * (((h >>> 16) * 6) >>> 16) + digit] * POW3_INV[j];
    h = hash32I(h ^ Math.imul(digit + 1 + 4 * j, 0x9e3779b1));
    a = next;
    j++;
  }
  const tail = ((hash32I(h ^ 0x68e31da4) >>> 5) * 67108864 + (hash32I(h ^ 0x1b56c4e9) >>> 6)) * TWO_POW_M53;
  x += tail * 3 * POW3_INV[j];
  return x < ONE_MINUS_EPS ? x : ONE_MINUS_EPS;
}

/**
 * Counter-based uniform double in [0, 1) from (seed hashes s1, s2, index i, dimension d): two
 * chained 32-bit avalanche hashes give 27 + 26 random bits, as in {@link Rng.nextFloat}.
 * Deterministic per (seed, i, d), so any sub-range of a point set can be regenerated.
 * Domain: i integer in [0, 2^53), d small integer; returns k·2^-53 with k < 2^53.
 */
export function hashUniform(s1: number, s2: number, i: number, d: number): number {
  const lo = i | 0;
  const hi = i < 4294967296 ? 0 : Math.floor(i / 4294967296) | 0;
  // h1 is a bijection of lo for fixed (seed, d, hi); h2 mixes h1 again with the second seed hash,
  // so (h1, h2) never repeats for distinct indices
  const h1 = hash32I(lo ^ s1 ^ Math.imul(d + 1, 0x27d4eb2f) ^ Math.imul(hi, 0x85ebca6b));
  const h2 = hash32I(h1 ^ s2);
  return ((h1 >>> 5) * 67108864 + (h2 >>> 6)) * TWO_POW_M53;
}
