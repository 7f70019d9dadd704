/**
 * Axes of the hand-written SVG plots: round tick positions, their labels, and the Unicode
 * superscripts those labels (and other plain-text numbers, "1.5×10⁻⁵") are written with. Pure, no DOM.
 */

import { SUPERSCRIPT, superscript, unsuperscript } from '../core/format';

export { SUPERSCRIPT, superscript, unsuperscript };

/** "10ⁿ" for an integer exponent n (e.g. pow10Text(-3) = "10⁻³"). */
export function pow10Text(e: number): string {
  return `10${superscript(String(e))}`;
}

/**
 * How a tick step is chosen from the raw step (range / count) scaled to [1, 10):
 * 'round': the nearest of 1, 2, 5, 10 (so about `count` ticks, more or fewer);
 * 'atLeast': the smallest of 1, 2, 2.5, 5, 10 not below it (at most about `count` ticks).
 */
export type TickLadder = 'round' | 'atLeast';

/** The tick step for [lo, hi] with about `count` intervals. */
export function niceStep(lo: number, hi: number, count: number, ladder: TickLadder = 'round'): number {
  const raw = (hi - lo) / Math.max(1, count);
  const p = 10 ** Math.floor(Math.log10(raw));
  const m = raw / p;
  if (ladder === 'atLeast') return [1, 2, 2.5, 5, 10].map((k) => k * p).find((s) => s >= raw) ?? raw;
  return (m < 1.5 ? 1 : m < 3 ? 2 : m < 7 ? 5 : 10) * p;
}

/**
 * Round ticks covering [lo, hi]: every multiple of the step (niceStep) inside it, rounded to 12
 * significant digits (no 0.30000000000000004). An empty or non-finite range: [lo] with step 1.
 */
export function niceTicks(
  lo: number,
  hi: number,
  count = 5,
  ladder: TickLadder = 'round',
): { ticks: number[]; step: number } {
  if (!(hi > lo) || !Number.isFinite(hi - lo)) return { ticks: [lo], step: 1 };
  const step = niceStep(lo, hi, count, ladder);
  const ticks: number[] = [];
  for (let k = Math.ceil(lo / step); k * step <= hi + step * 1e-9; k++)
    ticks.push(Number((k * step).toPrecision(12)));
  return { ticks, step };
}

/**
 * A tick label: plain decimals (as many as the step needs: 0.25 keeps both) for ordinary sizes,
 * m×10ⁿ (never SI prefixes) for |v| ≥ 1e5 or steps below 1e-3, its mantissa with the digits down to
 * the step's (so neighbouring ticks never read the same); a real minus sign.
 */
export function tickLabel(v: number, step: number): string {
  if (v === 0 || Math.abs(v) < step * 1e-9) return '0';
  const av = Math.abs(v);
  if (av >= 1e5 || step < 1e-3) {
    const e = Math.floor(Math.log10(av));
    const m = v / 10 ** e;
    const sig = Math.min(15, Math.max(3, e - Math.floor(Math.log10(step)) + 2));
    const ms = Number(m.toPrecision(sig)).toString();
    const ex = superscript(String(e));
    return ms === '1' ? `10${ex}` : ms === '-1' ? `−10${ex}` : `${ms.replace('-', '−')}×10${ex}`;
  }
  let digits = 0;
  while (
    digits < 6 &&
    Math.abs(step * 10 ** digits - Math.round(step * 10 ** digits)) > 1e-9 * step * 10 ** digits
  )
    digits++;
  return v.toFixed(digits).replace('-', '−');
}
