/**
 * Numbers as text for people, shared by the readouts (ui/Readout.tsx `formatNumber`), the
 * practice pages (practice/model.ts `fmt`) and the scenes' counts (`formatCount`): pure, no DOM.
 */

import { superscript } from './axis';

/** How an exponent is written: 'e' → "1.5e-5" (plain text), 'times' → "1.5×10⁻⁵" (typeset). */
export type ExponentStyle = 'e' | 'times';

/**
 * `digits` significant digits, trailing zeros trimmed, no exponent for 1e-4 ≤ |x| < 1e9; outside
 * that range a trimmed mantissa and the exponent in `style`. Domain: finite x (callers choose
 * what a non-finite value reads as; here it is String(x)); digits 1 … 100.
 */
export function formatSignificant(x: number, digits: number, style: ExponentStyle): string {
  if (!Number.isFinite(x)) return String(x);
  if (x === 0) return '0';
  const ax = Math.abs(x);
  if (ax >= 1e-4 && ax < 1e9) {
    const s = x.toPrecision(digits);
    // toPrecision switches to "2.00000e+8" when the integer part has more digits than asked for
    if (!s.includes('e')) return s.includes('.') ? s.replace(/\.?0+$/, '') : s;
  }
  const [m, e] = x.toExponential(Math.max(0, digits - 1)).split('e');
  const mt = m!.includes('.') ? m!.replace(/\.?0+$/, '') : m!;
  return style === 'e' ? `${mt}e${e!.replace('+', '')}` : `${mt}×10${superscript(e!.replace('+', ''))}`;
}

/**
 * A sample count with comma thousands separators, as `n.toLocaleString('en')` writes a
 * non-negative integer, without Intl: the page's first toLocaleString loads ICU's number
 * formatting, ~25–40 ms of main-thread time in the scene's first render. Anything else
 * (negative, fractional, unsafe integers) goes to toLocaleString.
 */
export function formatCount(n: number): string {
  if (!Number.isSafeInteger(n) || n < 0 || Object.is(n, -0)) return n.toLocaleString('en');
  const s = String(n);
  let out = '';
  for (let i = 0; i < s.length; i++) {
    if (i > 0 && (s.length - i) % 3 === 0) out += ',';
    out += s[i];
  }
  return out;
}
