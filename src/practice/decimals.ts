/**
 * Decimals as typed, read at their precision: a number answer's own figures, and the decimal
 * constants inside a typed formula (`0.00187*exp(phi)`), which the checker reads by the same rule
 * as a number answer (check.ts): each stands for every value it is a correct rounding of.
 */
import { compileExpression, type CompiledFn } from '../core/expr';

/**
 * Precision of a plain decimal as typed: half a unit in its last digit and its significant
 * figures (leading zeros do not count; every other digit typed does, trailing zeros included).
 * `s` must be a plain decimal (digits, an optional point, an optional exponent).
 */
export function decimalPrecision(s: string): { halfUnit: number; sigFigs: number } {
  const m = /^[+-]?(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?$/.exec(s);
  if (!m) return { halfUnit: 0, sigFigs: Infinity };
  const frac = m[2] ?? '';
  const exp = Number(m[3] ?? 0);
  const sig = ((m[1] ?? '') + frac).replace(/^0+/, '').length;
  return { halfUnit: 0.5 * 10 ** (exp - frac.length), sigFigs: sig };
}

/** A decimal constant in a formula's text: where it stands, its value and its precision. */
export interface DecimalConstant {
  text: string;
  start: number;
  value: number;
  halfUnit: number;
  sigFigs: number;
}

/**
 * A number literal not inside a name (the 1 of log1p, the 2 of atan2 are not literals). Whole
 * numbers without a point or exponent (the 2 of `2*sin(theta)`) are exact and not listed.
 */
const LITERAL = /(?<![A-Za-z_\d.])(?:\d+\.\d*|\.\d+|\d+(?=[eE][+-]?\d))(?:[eE][+-]?\d+)?(?![A-Za-z_\d.])/g;

/** The rounded decimal constants of a formula's (normalised) text, in order. */
export function decimalConstants(text: string): DecimalConstant[] {
  const out: DecimalConstant[] = [];
  for (const m of text.matchAll(LITERAL)) {
    const value = Number(m[0]);
    if (!Number.isFinite(value) || value === 0) continue;
    out.push({ text: m[0], start: m.index, value, ...decimalPrecision(m[0]) });
  }
  return out;
}

/** The formula with each rounded constant moved to either end of its rounding interval. */
export interface ConstantNudges {
  constants: DecimalConstant[];
  /** For each constant, the formula with it at its lower and at its upper end. */
  nudged: [CompiledFn, CompiledFn][];
}

/** Compile the nudged formulas (null when the text has no rounded constant or one does not compile). */
export async function nudgeConstants(
  text: string,
  variables: readonly string[],
): Promise<ConstantNudges | null> {
  const constants = decimalConstants(text);
  if (!constants.length || constants.length > 8) return null;
  const nudged: [CompiledFn, CompiledFn][] = [];
  for (const c of constants) {
    const at = async (v: number) => {
      const src = `${text.slice(0, c.start)}(${v})${text.slice(c.start + c.text.length)}`;
      const r = await compileExpression(src, variables);
      return r.ok ? r.fn : null;
    };
    const lo = await at(c.value - c.halfUnit);
    const hi = await at(c.value + c.halfUnit);
    if (!lo || !hi) return null;
    nudged.push([lo, hi]);
  }
  return { constants, nudged };
}

/**
 * Whether g, whose rounded constants may each lie anywhere in their rounding intervals, can be f:
 * at every point f − g must lie within the first-order spread the constants allow (the sum over
 * the constants of how far moving each to an end of its interval moves g), plus `rtol` of f.
 * Points where f is not finite are skipped; at least half must remain.
 */
export function withinConstantPrecision(
  f: (...x: number[]) => number,
  g: CompiledFn,
  nudges: ConstantNudges,
  points: readonly number[][],
  rtol: number,
): boolean {
  let used = 0;
  for (const p of points) {
    const e = f(...p);
    if (!Number.isFinite(e)) continue;
    const s = g(...p);
    if (!Number.isFinite(s)) return false;
    let spread = 0;
    for (const [lo, hi] of nudges.nudged) spread += Math.max(Math.abs(lo(...p) - s), Math.abs(hi(...p) - s));
    if (Math.abs(s - e) > spread * (1 + 1e-6) + rtol * Math.abs(e) + 1e-300) return false;
    used++;
  }
  return used >= points.length / 2;
}
