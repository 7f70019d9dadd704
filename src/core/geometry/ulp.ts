/**
 * Stepping through the doubles one at a time (Java's Math.nextUp / nextDown, C's nextafter),
 * by reinterpreting the IEEE-754 bits through a shared Float64Array / BigInt64Array view.
 * Used to build "one ulp off tangent" rays for tests and the precision presets.
 */

const f64 = new Float64Array(1);
const i64 = new BigInt64Array(f64.buffer);

/**
 * The smallest double greater than x. Domain: any double; nextUp(+∞) = +∞, nextUp(NaN) = NaN,
 * nextUp(−0) = nextUp(0) = 2^-1074 (the smallest subnormal). Source: IEEE 754-2008 nextUp.
 */
export function nextUp(x: number): number {
  if (Number.isNaN(x) || x === Infinity) return x;
  if (x === 0) return Number.MIN_VALUE;
  f64[0] = x;
  i64[0] += x > 0 ? 1n : -1n;
  return f64[0];
}

/** The largest double less than x (IEEE 754-2008 nextDown): −nextUp(−x). */
export function nextDown(x: number): number {
  return -nextUp(-x);
}

/** Step n doubles away from x (n > 0 upward, n < 0 downward). */
export function nextAfterN(x: number, n: number): number {
  let y = x;
  if (n > 0) for (let i = 0; i < n; i++) y = nextUp(y);
  else for (let i = 0; i < -n; i++) y = nextDown(y);
  return y;
}

/**
 * Unit in the last place of x: the gap from |x| to the next double away from zero.
 * Domain: finite x; ulp(0) = 2^-1074.
 */
export function ulp(x: number): number {
  const a = Math.abs(x);
  return nextUp(a) - a;
}

/**
 * How many doubles lie between a and b (0 when equal): the "ulp distance", computed on the
 * monotone integer mapping of the bit patterns. Infinite when either is NaN or they differ in
 * finiteness; counts −0 and +0 as the same. Returned as a Number (exact below 2^53).
 */
export function ulpDistance(a: number, b: number): number {
  if (Number.isNaN(a) || Number.isNaN(b)) return Infinity;
  if (a === b) return 0;
  if (!Number.isFinite(a) || !Number.isFinite(b)) return Infinity;
  return Number(bigAbs(orderedBits(a) - orderedBits(b)));
}

function orderedBits(x: number): bigint {
  f64[0] = x;
  const bits = i64[0];
  // Negative doubles: map so the integer order matches the numeric order, with −0 → 0.
  return bits < 0n ? -(bits & 0x7fffffffffffffffn) : bits;
}

function bigAbs(x: bigint): bigint {
  return x < 0n ? -x : x;
}
