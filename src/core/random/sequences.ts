/**
 * Point sets on the unit square (and interval) for Monte Carlo integration, all deterministic
 * functions of (kind, seed, n, i), so any range [start, end) of a set can be generated on its own
 * (in batches, in workers) and equals the same range of the whole set.
 *
 * - independent: i.i.d. uniform points from a counter-based hash of (seed, i, dimension).
 * - stratified: jittered stratification with exactly one point per stratum (layout below).
 * - halton: Halton in bases 2 and 3 with Owen (nested random-digit) scrambling seeded by `seed`.
 * - sobol: Sobol' dimensions 0 and 1 (Joe–Kuo), Owen-scrambled and index-shuffled (Burley 2020).
 *
 * Every value is in [0, 1), never 1. Source: pbrt-v4 §8.2–8.7 (samplers); Owen (1995);
 * Burley (2020) "Practical Hash-based Owen Scrambling", JCGT 9(4).
 */
import { ONE_MINUS_EPS, toSeed } from './rng';
import {
  hash32I,
  hashCombine,
  hashUniform,
  owenHashReversedI,
  owenRadicalInverse3,
  reverseBits32I,
  TWO_POW_M32,
} from './owen';
import { SOBOL_DIM1_BYTES as DIM1_I } from './sobol';

// Local aliases of the per-point helpers. In the bundled app they change nothing; under Vite's
// module runner (vitest, vitest bench) every use of an imported binding is a property read on the
// module namespace, which blocks inlining and made these loops up to 100× slower there.
const hashUniformL = hashUniform;
const owenRadicalInverse3L = owenRadicalInverse3;
const owenHashReversedIL = owenHashReversedI;
const reverseBits32IL = reverseBits32I;
const DIM1_L = DIM1_I;
const TWO_POW_M32_L = TWO_POW_M32;
const ONE_MINUS_EPS_L = ONE_MINUS_EPS;

/** The sample-sequence families offered by the scenes. */
export type SequenceKind = 'independent' | 'stratified' | 'halton' | 'sobol';

/** All sequence kinds, in the order the UI lists them. */
export const SEQUENCE_KINDS: readonly SequenceKind[] = ['independent', 'stratified', 'halton', 'sobol'];

/** Largest supported point count (indices are 32-bit for Halton/Sobol). */
export const MAX_SEQUENCE_POINTS = 4294967296;

/**
 * Layout of the stratified 2D set of n points (pad-free, any n ≥ 1): the square is cut into
 * a = round(√n) horizontal rows; the first n − a·⌊n/a⌋ rows hold ⌊n/a⌋ + 1 cells, the others ⌊n/a⌋.
 * A row with k cells has height k/n and its cells width 1/k, so every cell has area exactly 1/n
 * and is roughly square. When n = a·b (a ≈ √n) this is the ordinary a × b jittered grid; for a
 * prime n it is still near-square cells rather than 1 × n slivers. Cells are numbered row by row,
 * bottom to top (ξ2), left to right (ξ1); point i lies in cell i, jittered uniformly inside it.
 *
 * Returns the cell of point i: k = number of cells in its row, c = its column, y0 = (i − c)/n the
 * row's lower edge and height = k/n; the cell is [c/k, (c+1)/k) × [y0, y0 + height).
 * Domain: n ≥ 1, 0 ≤ i < n.
 * Note: because cells are numbered row by row, a prefix of a stratified set is not stratified
 * (use a new n-point set per N, as the convergence runs do).
 */
export function stratifiedCell(n: number, i: number): { k: number; c: number; y0: number; height: number } {
  const a = Math.max(1, Math.round(Math.sqrt(n)));
  const base = Math.floor(n / a);
  const extra = n - a * base; // rows with base + 1 cells
  const bigRows = extra * (base + 1);
  let k: number;
  let c: number;
  if (i < bigRows) {
    k = base + 1;
    c = i % k;
  } else {
    k = base;
    c = (i - bigRows) % k;
  }
  return { k, c, y0: (i - c) / n, height: k / n };
}

/** The four 32-bit hashes (int32) of a seed that drive the sequences (exported for tests). */
export function sequenceSeedHashes(seed: number): [number, number, number, number] {
  const s = hash32I(toSeed(seed) ^ 0x3c6ef372);
  return [s, hash32I(s ^ 0x01000193), hash32I(s ^ 0x7f4a7c15), hash32I(s ^ 0x61c88647)];
}

function checkRange(
  n: number,
  out: Float64Array,
  dim: number,
  start: number,
  end: number,
  offset: number,
): void {
  if (!(Number.isInteger(n) && n >= 0 && n <= MAX_SEQUENCE_POINTS)) {
    throw new RangeError(`point count n must be an integer in [0, 2^32], got ${n}`);
  }
  if (!(Number.isInteger(start) && Number.isInteger(end) && 0 <= start && start <= end && end <= n)) {
    throw new RangeError(`range [${start}, ${end}) must lie within [0, ${n})`);
  }
  if (!(Number.isInteger(offset) && offset >= 0 && out.length >= dim * (offset + end - start))) {
    throw new RangeError(
      `output buffer of length ${out.length} is too short for ${end - start} points at offset ${offset}`,
    );
  }
}

/** Largest double strictly below hi (for hi > 0), used to keep jittered points inside their cell. */
function below(x: number, hi: number): number {
  return x < hi ? x : hi * (1 - 2.220446049250313e-16);
}

/**
 * Fill points [start, end) of the n-point 2D set of the given kind into `out`, ξ1 and ξ2
 * interleaved. Point i is written at out[2(i − start + outOffset)], out[2(i − start + outOffset) + 1];
 * the default outOffset = start puts it at out[2i] (a buffer of length 2n for the whole set),
 * outOffset = 0 fills a batch buffer of length 2(end − start).
 *
 * Domain: n integer in [0, 2^32]; 0 ≤ start ≤ end ≤ n; seed any number (coerced to uint32).
 * Range: every coordinate in [0, 1), never 1. Measure: uniform on the unit square (each point's
 * marginal distribution is uniform for every kind). Throws RangeError for an impossible range or a
 * short buffer. Deterministic in (kind, seed, n, i); the `independent`, `halton` and `sobol`
 * points do not depend on n (they are prefixes of one infinite sequence).
 * Source: see the module comment.
 */
export function fillSequence2D(
  kind: SequenceKind,
  seed: number,
  n: number,
  out: Float64Array,
  start = 0,
  end = n,
  outOffset = start,
): Float64Array {
  checkRange(n, out, 2, start, end, outOffset);
  const [s0, s1, s2, s3] = sequenceSeedHashes(seed);
  let o = 2 * outOffset;
  switch (kind) {
    case 'independent':
      for (let i = start; i < end; i++, o += 2) {
        out[o] = hashUniformL(s0, s1, i, 0);
        out[o + 1] = hashUniformL(s0, s1, i, 1);
      }
      break;
    case 'stratified':
      // one stratifiedCell per row (not per point): the row's cells are consecutive indices
      for (let i = start; i < end;) {
        const { k, c: c0, y0, height } = stratifiedCell(n, i);
        const rowEnd = Math.min(end, i - c0 + k);
        const top = y0 + height;
        for (let c = c0; i < rowEnd; i++, c++, o += 2) {
          const ux = hashUniformL(s2, s3, i, 0);
          const uy = hashUniformL(s2, s3, i, 1);
          out[o] = Math.min(below((c + ux) / k, (c + 1) / k), ONE_MINUS_EPS_L);
          out[o + 1] = Math.min(below(y0 + uy * height, top), ONE_MINUS_EPS_L);
        }
      }
      break;
    case 'halton': {
      const hb2 = hashCombine(s0, 2) | 0;
      const hb3 = hashCombine(s1, 3) | 0;
      for (let i = start; i < end; i++, o += 2) {
        // Owen-scrambled van der Corput: owen(rev(i)) = rev(hash(i))
        out[o] = (reverseBits32IL(owenHashReversedIL(i | 0, hb2)) >>> 0) * TWO_POW_M32_L;
        out[o + 1] = owenRadicalInverse3L(i, hb3);
      }
      break;
    }
    case 'sobol':
      sobolKernel(out, o, start, end, s1, s2, s3, 2);
      break;
    default:
      throw new RangeError(`unknown sequence kind '${String(kind)}'`);
  }
  return out;
}

/**
 * Fill values [start, end) of the n-value 1D set of the given kind into `out` (value i at
 * out[i − start + outOffset]; default outOffset = start, i.e. out[i]).
 * independent: hashed uniforms; stratified: (i + u_i)/n, one value per interval [i/n, (i+1)/n);
 * halton: Owen-scrambled van der Corput (base 2); sobol: dimension 0 of the shuffled, scrambled
 * Sobol' sequence (also a scrambled van der Corput sequence, in shuffled order).
 * Domain, range and errors as for {@link fillSequence2D}; values in [0, 1).
 */
export function fillSequence1D(
  kind: SequenceKind,
  seed: number,
  n: number,
  out: Float64Array,
  start = 0,
  end = n,
  outOffset = start,
): Float64Array {
  checkRange(n, out, 1, start, end, outOffset);
  const [s0, s1, s2, s3] = sequenceSeedHashes(seed);
  let o = outOffset;
  switch (kind) {
    case 'independent':
      for (let i = start; i < end; i++, o++) out[o] = hashUniformL(s0, s1, i, 0);
      break;
    case 'stratified':
      for (let i = start; i < end; i++, o++) {
        const u = hashUniformL(s2, s3, i, 0);
        out[o] = Math.min(below((i + u) / n, (i + 1) / n), ONE_MINUS_EPS_L);
      }
      break;
    case 'halton': {
      const hb2 = hashCombine(s0, 2) | 0;
      for (let i = start; i < end; i++, o++)
        out[o] = (reverseBits32IL(owenHashReversedIL(i | 0, hb2)) >>> 0) * TWO_POW_M32_L;
      break;
    }
    case 'sobol':
      sobolKernel(out, o, start, end, s1, s2, s3, 1);
      break;
    default:
      throw new RangeError(`unknown sequence kind '${String(kind)}'`);
  }
  return out;
}

/**
 * Shuffled, Owen-scrambled Sobol' points [start, end) written from out[o] on, `dims` (1 or 2) values
 * per point. The same arithmetic as `shuffledSobol2Bits` (sobol.ts): index j = owen(i), then
 * x0 = owen(rev(j)) = rev(hash(j)), x1 = owen(sobol1(j)) = rev(hash(rev(sobol1(j)))). Written out by
 * hand, without helper calls: engines stop inlining after a budget, and a non-inlined helper that
 * returns a 32-bit value outside the small-integer range allocates, which made this 20× slower.
 * Re-measured (interleaved A/B against this kernel, bit-identical output, Node 20):
 * the same loop written with owen.ts's reverseBits32I / owenHashReversedI (multiplier hoisted or
 * not), or with local helpers, ran 15–35 % slower per point, so the repeated rev/hash steps stay
 * written out (a hand-inlined twin stays where it is measurably faster, said beside it).
 */
function sobolKernel(
  out: Float64Array,
  o: number,
  start: number,
  end: number,
  s1: number,
  s2: number,
  s3: number,
  dims: 1 | 2,
): void {
  const m1 = (s1 >>> 16) | 1;
  const m2 = (s2 >>> 16) | 1;
  const m3 = (s3 >>> 16) | 1;
  for (let i = start; i < end; i++, o += dims) {
    // j = rev(hash_s1(rev(i)))
    let v = i | 0;
    v = ((v >>> 1) & 0x55555555) | ((v & 0x55555555) << 1);
    v = ((v >>> 2) & 0x33333333) | ((v & 0x33333333) << 2);
    v = ((v >>> 4) & 0x0f0f0f0f) | ((v & 0x0f0f0f0f) << 4);
    v = ((v >>> 8) & 0x00ff00ff) | ((v & 0x00ff00ff) << 8);
    v = (v >>> 16) | (v << 16);
    v ^= Math.imul(v, 0x3d20adea);
    v = (v + s1) | 0;
    v = Math.imul(v, m1);
    v ^= Math.imul(v, 0x05526c56);
    v ^= Math.imul(v, 0x53a22864);
    v = ((v >>> 1) & 0x55555555) | ((v & 0x55555555) << 1);
    v = ((v >>> 2) & 0x33333333) | ((v & 0x33333333) << 2);
    v = ((v >>> 4) & 0x0f0f0f0f) | ((v & 0x0f0f0f0f) << 4);
    v = ((v >>> 8) & 0x00ff00ff) | ((v & 0x00ff00ff) << 8);
    const j = (v >>> 16) | (v << 16);
    // x0 = rev(hash_s2(j))
    let a = j;
    a ^= Math.imul(a, 0x3d20adea);
    a = (a + s2) | 0;
    a = Math.imul(a, m2);
    a ^= Math.imul(a, 0x05526c56);
    a ^= Math.imul(a, 0x53a22864);
    a = ((a >>> 1) & 0x55555555) | ((a & 0x55555555) << 1);
    a = ((a >>> 2) & 0x33333333) | ((a & 0x33333333) << 2);
    a = ((a >>> 4) & 0x0f0f0f0f) | ((a & 0x0f0f0f0f) << 4);
    a = ((a >>> 8) & 0x00ff00ff) | ((a & 0x00ff00ff) << 8);
    out[o] = (((a >>> 16) | (a << 16)) >>> 0) * TWO_POW_M32_L;
    if (dims === 1) continue;
    // x1 = rev(hash_s3(rev(sobol1(j))))
    let b =
      DIM1_L[j & 255] ^
      DIM1_L[256 + ((j >>> 8) & 255)] ^
      DIM1_L[512 + ((j >>> 16) & 255)] ^
      DIM1_L[768 + (j >>> 24)];
    b = ((b >>> 1) & 0x55555555) | ((b & 0x55555555) << 1);
    b = ((b >>> 2) & 0x33333333) | ((b & 0x33333333) << 2);
    b = ((b >>> 4) & 0x0f0f0f0f) | ((b & 0x0f0f0f0f) << 4);
    b = ((b >>> 8) & 0x00ff00ff) | ((b & 0x00ff00ff) << 8);
    b = (b >>> 16) | (b << 16);
    b ^= Math.imul(b, 0x3d20adea);
    b = (b + s3) | 0;
    b = Math.imul(b, m3);
    b ^= Math.imul(b, 0x05526c56);
    b ^= Math.imul(b, 0x53a22864);
    b = ((b >>> 1) & 0x55555555) | ((b & 0x55555555) << 1);
    b = ((b >>> 2) & 0x33333333) | ((b & 0x33333333) << 2);
    b = ((b >>> 4) & 0x0f0f0f0f) | ((b & 0x0f0f0f0f) << 4);
    b = ((b >>> 8) & 0x00ff00ff) | ((b & 0x00ff00ff) << 8);
    out[o + 1] = (((b >>> 16) | (b << 16)) >>> 0) * TWO_POW_M32_L;
  }
}
