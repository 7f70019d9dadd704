/**
 * Double-double arithmetic: a value is the unevaluated sum hi + lo of two doubles with
 * |lo| ≤ ½ ulp(hi), about 106 significant bits. Built from the error-free transformations
 * TwoSum (Knuth, TAOCP vol. 2, §4.2.2) and TwoProduct (Dekker 1971, "A floating-point technique
 * for extending the available precision", with Veltkamp's splitting), as in the QD library
 * (Hida, Li & Bailey 2001) and Shewchuk's "Adaptive precision floating-point arithmetic" (1997).
 *
 * Used here as the in-page high-precision reference for the ray–sphere roots (the page cannot
 * afford mathjs BigNumber on every drag); the tests check it against mathjs BigNumber.
 *
 * Domain: finite doubles with |x| ≤ 2^996 (Veltkamp's split overflows above that). Results are
 * pairs [hi, lo]; functions allocate small tuples, so keep them out of per-pixel hot loops.
 */

/** A double-double number hi + lo (|lo| ≤ ½ ulp(hi)). */
export type DD = readonly [hi: number, lo: number];

const SPLITTER = 134217729; // 2^27 + 1 (Veltkamp)

/**
 * TwoSum (Knuth): returns [s, e] with s = fl(a + b) and s + e = a + b exactly.
 * Domain: finite doubles whose sum does not overflow. No branch on magnitudes.
 */
export function twoSum(a: number, b: number): DD {
  const s = a + b;
  const bb = s - a;
  const e = a - (s - bb) + (b - bb);
  return [s, e];
}

/** Veltkamp split: a = hi + lo exactly, hi and lo with at most 26 significant bits each. |a| ≤ 2^996. */
export function split(a: number): DD {
  const c = SPLITTER * a;
  const hi = c - (c - a);
  return [hi, a - hi];
}

/**
 * TwoProduct (Dekker): returns [p, e] with p = fl(a·b) and p + e = a·b exactly
 * (barring underflow of e). Domain: |a|, |b| ≤ 2^996, no overflow of a·b.
 */
export function twoProduct(a: number, b: number): DD {
  const p = a * b;
  const [ah, al] = split(a);
  const [bh, bl] = split(b);
  const e = ah * bh - p + ah * bl + al * bh + al * bl;
  return [p, e];
}

/** Renormalise hi + lo so that |lo| ≤ ½ ulp(hi) (Fast2Sum; needs |hi| ≥ |lo| or hi = 0). */
function quickTwoSum(a: number, b: number): DD {
  const s = a + b;
  return [s, b - (s - a)];
}

/** x + y in double-double (QD's "sloppy" add is not used: this is the accurate IEEE-style add). */
export function ddAdd(x: DD, y: DD): DD {
  const [s1, s2] = twoSum(x[0], y[0]);
  const [t1, t2] = twoSum(x[1], y[1]);
  let [hi, lo] = quickTwoSum(s1, s2 + t1);
  [hi, lo] = quickTwoSum(hi, lo + t2);
  return [hi, lo];
}

/** −x. */
export function ddNeg(x: DD): DD {
  return [-x[0], -x[1]];
}

/** x − y in double-double. */
export function ddSub(x: DD, y: DD): DD {
  return ddAdd(x, ddNeg(y));
}

/** x · y in double-double (relative error ≲ 2^-104 barring under/overflow). */
export function ddMul(x: DD, y: DD): DD {
  const [p, e] = twoProduct(x[0], y[0]);
  return quickTwoSum(p, e + (x[0] * y[1] + x[1] * y[0]));
}

/** x / y in double-double (long division with one correction step). y ≠ 0. */
export function ddDiv(x: DD, y: DD): DD {
  const q1 = x[0] / y[0];
  const r = ddSub(x, ddMul(y, [q1, 0]));
  const q2 = r[0] / y[0];
  const r2 = ddSub(r, ddMul(y, [q2, 0]));
  const q3 = r2[0] / y[0];
  const [hi, lo] = quickTwoSum(q1, q2);
  return ddAdd([hi, lo], [q3, 0]);
}

/** √x in double-double (Karp–Markstein: one Newton step from the double sqrt). x ≥ 0; √0 = 0. */
export function ddSqrt(x: DD): DD {
  if (x[0] <= 0) return [0, 0];
  const s = Math.sqrt(x[0]);
  // s + (x − s²) / (2s): one Newton step doubles the number of correct bits.
  const r = ddSub(x, twoProduct(s, s));
  const corr = r[0] / (2 * s);
  return quickTwoSum(s, corr);
}

/** Sign of a double-double: −1, 0 or 1 (decided by hi, which carries the sign unless hi = 0). */
export function ddSign(x: DD): -1 | 0 | 1 {
  if (x[0] > 0) return 1;
  if (x[0] < 0) return -1;
  return x[1] > 0 ? 1 : x[1] < 0 ? -1 : 0;
}

/** The nearest double to hi + lo. */
export function ddToNumber(x: DD): number {
  return x[0] + x[1];
}
