/**
 * Units in the last place of IEEE single precision (float32), the format GPUs compute in:
 * 24-bit significands, unit roundoff u₃₂ = 2⁻²⁴ ≈ 6.0e-8 (against 2⁻⁵³ ≈ 1.1e-16 for doubles).
 * Bits are read through a shared Float32Array / Int32Array view.
 */

const f32 = new Float32Array(1);
const i32 = new Int32Array(f32.buffer);

/** Unit roundoff of float32: 2⁻²⁴ (half the gap from 1 to the next float32). */
export const U32 = 2 ** -24;

/** The largest finite float32, (2 − 2⁻²³)·2¹²⁷ ≈ 3.4028e38. */
export const F32_MAX = 3.4028234663852886e38;

/**
 * The gap from |x| to the next float32 away from zero, for x rounded to float32 first.
 * Domain: finite x with |x| ≤ F32_MAX; ulpF32(0) = 2⁻¹⁴⁹ (the smallest subnormal).
 */
export function ulpF32(x: number): number {
  const a = Math.abs(Math.fround(x));
  if (a >= F32_MAX) return 2 ** 104; // the gap below the largest float32
  f32[0] = a;
  i32[0] += 1;
  return f32[0] - a;
}

/**
 * How many float32 values lie between a and b (0 when equal), both rounded to float32 first;
 * Infinity when either is NaN or they differ in finiteness; −0 and +0 count as the same.
 */
export function ulpDistanceF32(a: number, b: number): number {
  const x = Math.fround(a);
  const y = Math.fround(b);
  if (Number.isNaN(x) || Number.isNaN(y)) return Infinity;
  if (x === y) return 0;
  if (!Number.isFinite(x) || !Number.isFinite(y)) return Infinity;
  return Math.abs(orderedBits32(x) - orderedBits32(y));
}

/**
 * The error of a float32 result against a real-valued (double) reference, in float32 ulps of the
 * reference: |x − ref| / ulp₃₂(ref). A fraction below 1 for a correctly rounded result
 * (at most ½). Infinity when one of them is missing or not finite and the other is not.
 */
export function errorInUlpsF32(x: number | null, ref: number | null): number {
  if (x === null && ref === null) return 0;
  if (x === null || ref === null || !Number.isFinite(x) || !Number.isFinite(ref)) return Infinity;
  return Math.abs(x - ref) / ulpF32(ref);
}

function orderedBits32(x: number): number {
  f32[0] = x;
  const bits = i32[0];
  // Negative floats: map so the integer order matches the numeric order, with −0 → 0.
  return bits < 0 ? -(bits & 0x7fffffff) : bits;
}
