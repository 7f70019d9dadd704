/**
 * Texture addressing ("wrap modes"): what a lookup does with a coordinate outside [0, 1] or a texel
 * index outside 0 … N − 1. Two forms, because the two node conventions need different ones:
 *
 * - {@link addressCoord} maps a continuous coordinate t into [0, 1]. It is used with the exam's
 *   corner-aligned nodes (i / (N − 1)), whose nodes cover [0, 1] exactly, so the texture is a
 *   function on [0, 1] and addressing extends it to the whole line.
 * - {@link addressIndex} maps an integer texel index into 0 … N − 1. It is used with the GPU's
 *   texel centres ((i + ½) / N), per tap, exactly as OpenGL does it (OpenGL 4.6 core spec §8.14.2,
 *   table 8.20: CLAMP_TO_EDGE, REPEAT, MIRRORED_REPEAT), so a bilinear stencil may straddle the
 *   edge (last and first texel) under repeat.
 *
 * Source: pbrt-v4 `WrapMode` / `RemapPixelCoords` (textures/image.h) for the index form.
 */

/** How a coordinate outside [0, 1] (or an index outside 0 … N − 1) is brought back. */
export type WrapMode = 'clamp' | 'repeat' | 'mirror';

/** The wrap modes, in the order the scene lists them. */
export const WRAP_MODES: readonly WrapMode[] = ['clamp', 'repeat', 'mirror'];

/**
 * Map a continuous texture coordinate t into [0, 1].
 *
 * Domain: any finite t (non-finite t → 0, a safe fallback). Exactness: every t already in [0, 1]
 * (including exactly 0 and exactly 1) is returned unchanged in every mode, so addressing never
 * changes an in-range lookup.
 * - clamp: min(max(t, 0), 1).
 * - repeat: outside [0, 1], the fractional part t − ⌊t⌋ ∈ [0, 1) (so 1.25 → 0.25, −0.25 → 0.75,
 *   2 → 0, −1 → 0). Inside [0, 1] unchanged, so t = 1 stays the right edge.
 * - mirror: reflection with period 2: m = t mod 2 ∈ [0, 2), then m ≤ 1 ? m : 2 − m
 *   (1.25 → 0.75, −0.25 → 0.25, 2 → 0, −1 → 1). Continuous everywhere.
 */
export function addressCoord(t: number, mode: WrapMode): number {
  if (!Number.isFinite(t)) return 0;
  if (t >= 0 && t <= 1) return t;
  switch (mode) {
    case 'clamp':
      return t < 0 ? 0 : 1;
    case 'repeat': {
      // fmod is exact; + 1 can round up to exactly 1 for tiny negative t (−1e-17 + 1 = 1): wrap to 0.
      let f = t % 1;
      if (f < 0) f += 1;
      return f >= 1 ? 0 : f + 0; // + 0 turns −0 into +0
    }
    case 'mirror': {
      let m = t % 2; // exact
      if (m < 0) m += 2;
      if (m >= 2) m = 0; // rounding guard, as above
      return m <= 1 ? m + 0 : 2 - m;
    }
  }
}

/**
 * Map an integer texel index i into 0 … n − 1 (n ≥ 1), as a GPU does for each tap.
 *
 * Domain: integer i (any sign), integer n ≥ 1.
 * - clamp (CLAMP_TO_EDGE): min(max(i, 0), n − 1).
 * - repeat (REPEAT): i mod n, always non-negative.
 * - mirror (MIRRORED_REPEAT): m = i mod 2n; m < n ? m : 2n − 1 − m (so −1 → 0, n → n − 1).
 */
export function addressIndex(i: number, n: number, mode: WrapMode): number {
  switch (mode) {
    case 'clamp':
      return i < 0 ? 0 : i >= n ? n - 1 : i;
    case 'repeat': {
      return ((i % n) + n) % n; // non-negative, and +0 rather than −0
    }
    case 'mirror': {
      const p = 2 * n;
      const m = ((i % p) + p) % p;
      return m < n ? m : p - 1 - m;
    }
  }
}
