/**
 * Summing many samples in float32, as the GPU renderer's accumulation target does, emulated exactly
 * in JavaScript with Math.fround after every operation: the naive running sum s ← s + x, and Kahan's
 * compensated sum (Kahan 1965), which carries the low-order bits each addition loses in a second
 * number c and feeds them back into the next addition:
 *
 *     y = x − c,   t = s + y,   c = (t − s) − y,   s = t.
 *
 * The naive sum of n terms can be off by up to (n − 1) u Σ|xᵢ| (u = 2⁻²⁴ in float32); the compensated
 * sum by 2u Σ|xᵢ| + O(n u²) Σ|xᵢ|, independent of n to first order (Higham, "Accuracy and Stability
 * of Numerical Algorithms", 2nd ed., 2002, §4.2 and §4.3). pbrt-v4 keeps its pixel sums as
 * compensated floats for the same reason (`CompensatedFloat`, util/math.h).
 */

/** Unit roundoff of float32 (half its machine epsilon). */
export const F32_UNIT_ROUNDOFF = 2 ** -24;
/** Unit roundoff of float64. */
export const F64_UNIT_ROUNDOFF = 2 ** -53;

const f = Math.fround;

/** A float32 running sum in both forms, as the accumulation target's R, G and B channels hold it. */
export interface F32Sums {
  /** The naive float32 sum. */
  naive: number;
  /** Kahan's compensated float32 sum and its compensation term c. */
  kahan: number;
  comp: number;
}

export function newF32Sums(): F32Sums {
  return { naive: 0, kahan: 0, comp: 0 };
}

/** Add x (rounded to float32 first, as a shader's output is) to both sums, in float32 arithmetic. */
export function addF32(s: F32Sums, x: number): void {
  const xf = f(x);
  s.naive = f(s.naive + xf);
  const y = f(xf - s.comp);
  const t = f(s.kahan + y);
  s.comp = f(f(t - s.kahan) - y);
  s.kahan = t;
}

/** Both float32 sums of a sequence of terms. */
export function sumF32(xs: Iterable<number>): F32Sums {
  const s = newF32Sums();
  for (const x of xs) addF32(s, x);
  return s;
}

/**
 * The float32 cost over an image: the mean over pixels of |naive − Kahan| / |Kahan|, from the
 * accumulation target's channels (RGBA per pixel: naive, Kahan, compensation, sum of squares);
 * pixels whose Kahan sum is 0 are skipped. NaN when no pixel counts.
 */
export function naiveSumError(rgba: ArrayLike<number>): number {
  let total = 0;
  let n = 0;
  for (let k = 0; k + 3 < rgba.length; k += 4) {
    const kahan = rgba[k + 1];
    if (!(Math.abs(kahan) > 0)) continue;
    total += Math.abs(rgba[k] - kahan) / Math.abs(kahan);
    n++;
  }
  return n > 0 ? total / n : NaN;
}

/** Higham's bound on the relative error of a naive sum of n terms of one sign: (n − 1) u / (1 − (n − 1) u). */
export function naiveSumBound(n: number, u: number): number {
  const k = Math.max(0, n - 1) * u;
  return k < 1 ? k / (1 - k) : Infinity;
}
