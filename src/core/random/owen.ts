/**
 * Bit-level helpers for scrambled low-discrepancy sequences: 32-bit reversal, hash-based Owen
 * scrambling in base 2, Owen-scrambled radical inverse in base 3, and counter-based uniform
 * hashing. All integer arithmetic is 32-bit (Math.imul), identical on every engine.
 */
import { mix32, ONE_MINUS_EPS, TWO_POW_M53 } from './rng';

/** 2^-32: converts a uint32 to a double in [0, 1). */
export const TWO_POW_M32 = 1 / 4294967296;

/** Reverse the 32 bits of a uint32 (bit 0 ↔ bit 31). Domain: any uint32; returns a uint32. */
export function reverseBits32(v: number): number {
  v = ((v >>> 1) & 0x55555555) | ((v & 0x55555555) << 1);
  v = ((v >>> 2) & 0x33333333) | ((v & 0x33333333) << 2);
  v = ((v >>> 4) & 0x0f0f0f0f) | ((v & 0x0f0f0f0f) << 4);
  v = ((v >>> 8) & 0x00ff00ff) | ((v & 0x00ff00ff) << 8);
  return ((v >>> 16) | (v << 16)) >>> 0;
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
  v = reverseBits32(v);
  // each step below only lets lower bits (= more significant digits before reversal) affect higher
  v ^= Math.imul(v, 0x3d20adea);
  v = (v + seed) | 0;
  v = Math.imul(v, (seed >>> 16) | 1);
  v ^= Math.imul(v, 0x05526c56);
  v ^= Math.imul(v, 0x53a22864);
  return reverseBits32(v >>> 0);
}

/** Combine two uint32 hashes (order matters). Returns a uint32. */
export function hashCombine(a: number, b: number): number {
  return mix32((a ^ Math.imul(mix32(b), 0x9e3779b1)) >>> 0);
}

// The six permutations of {0, 1, 2}, flattened.
const PERM3 = new Uint8Array([0, 1, 2, 0, 2, 1, 1, 0, 2, 1, 2, 0, 2, 0, 1, 2, 1, 0]);

/**
 * Owen-scrambled radical inverse in base 3 of a non-negative integer index: digit j of the index
 * (least significant first) becomes digit j after the ternary point, permuted by one of the six
 * permutations of {0,1,2} chosen by a hash of `seed` and the digits before it (nested scrambling).
 * Leading zero digits are permuted too, so the result is uniform on [0, 1) down to 3^-34.
 * Domain: index integer in [0, 2^53), seed uint32; returns a double in [0, 1).
 * Source: pbrt-v4 `OwenScrambledRadicalInverse` (util/lowdiscrepancy.h), Owen (1995).
 */
export function owenRadicalInverse3(index: number, seed: number): number {
  let a = index;
  let h = seed >>> 0;
  let scale = 1 / 3;
  let x = 0;
  for (let j = 0; j < 34; j++) {
    const next = Math.floor(a / 3);
    const digit = a - 3 * next;
    const p = mix32(h) % 6;
    x += PERM3[3 * p + digit]! * scale;
    h = hashCombine(h, digit + 1 + 4 * j);
    scale /= 3;
    a = next;
  }
  return x < ONE_MINUS_EPS ? x : ONE_MINUS_EPS;
}

/**
 * Counter-based uniform double in [0, 1) from (seed hashes s1, s2, index i, dimension d): two
 * independent 32-bit avalanche hashes give 27 + 26 random bits, as in {@link Rng.nextFloat}.
 * Deterministic per (seed, i, d), so any sub-range of a point set can be regenerated.
 * Domain: i integer in [0, 2^53), d small integer; returns k·2^-53 with k < 2^53.
 */
export function hashUniform(s1: number, s2: number, i: number, d: number): number {
  const lo = i >>> 0;
  const hi = Math.floor(i / 4294967296) >>> 0;
  const k = (lo ^ Math.imul(hi, 0x85ebca6b) ^ Math.imul(d + 1, 0x27d4eb2f)) >>> 0;
  const a = mix32((mix32((k ^ s1) >>> 0) + hi) >>> 0) >>> 5;
  const b = mix32((mix32((k ^ s2) >>> 0) + Math.imul(d, 0x165667b1)) >>> 0) >>> 6;
  return (a * 67108864 + b) * TWO_POW_M53;
}
