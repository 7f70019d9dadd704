/**
 * The one number formatter of the project: numbers as text for people, for the core's messages,
 * the URL layer, the readouts, the scenes' figures and counts, and the practice pages. Pure, no
 * DOM, so every layer may use it (src/ui/format.ts hands the same functions on to the views).
 */

/** Unicode superscript of each character that has one (no prototype: any key is a plain lookup). */
export const SUPERSCRIPT: Readonly<Record<string, string>> = Object.assign(
  Object.create(null) as Record<string, string>,
  {
    '0': '⁰',
    '1': '¹',
    '2': '²',
    '3': '³',
    '4': '⁴',
    '5': '⁵',
    '6': '⁶',
    '7': '⁷',
    '8': '⁸',
    '9': '⁹',
    '+': '⁺',
    '-': '⁻',
    '−': '⁻',
    '=': '⁼',
    '(': '⁽',
    ')': '⁾',
    n: 'ⁿ',
    i: 'ⁱ',
    T: 'ᵀ',
  },
);

/** The plain character of each superscript digit and sign ("⁻" reads back as "-"). */
const PLAIN: Readonly<Record<string, string>> = Object.assign(Object.create(null) as Record<string, string>, {
  '⁰': '0',
  '¹': '1',
  '²': '2',
  '³': '3',
  '⁴': '4',
  '⁵': '5',
  '⁶': '6',
  '⁷': '7',
  '⁸': '8',
  '⁹': '9',
  '⁺': '+',
  '⁻': '-',
});

/** `text` with each character that has a superscript raised; others are kept. */
export function superscript(text: string): string {
  let out = '';
  for (const ch of text) out += SUPERSCRIPT[ch] ?? ch;
  return out;
}

/** Superscript digits and signs back to plain ones ("⁻¹²" → "-12"); others are kept. */
export function unsuperscript(text: string): string {
  let out = '';
  for (const ch of text) out += PLAIN[ch] ?? ch;
  return out;
}

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

/** Visible text of a number: `digits` significant digits, trailing zeros trimmed, "×10⁻⁵" style; "—" when not finite. */
export function formatNumber(x: number, digits = 6): string {
  return Number.isFinite(x) ? formatSignificant(x, digits, 'times') : '—';
}

/**
 * Plain-text number for messages and URLs: integers as they are, others to `digits` significant
 * digits with trailing zeros trimmed and "e" exponents ("0.00123", "1.5e-7").
 */
export function formatPlain(x: number, digits = 6): string {
  return Number.isInteger(x) ? String(x) : formatSignificant(x, digits, 'e');
}

/**
 * `x` with exactly `decimals` digits after the point (as toFixed), never a negative zero ("-0",
 * "-0.00" read as "0", "0.00"): for coordinates written into SVG attributes and paths.
 */
export function formatFixed(x: number, decimals: number): string {
  const s = x.toFixed(decimals);
  return /^-0(\.0*)?$/.test(s) ? s.slice(1) : s;
}

/**
 * Short text of a number for labels inside figures: x rounded to `digits` significant digits and
 * written as JavaScript writes that rounded number ("17.8", "12350", "0.00001", "1e-7"), so no
 * trailing zeros and no exponent for ordinary sizes; "—" when not finite.
 */
export function formatRounded(x: number, digits = 4): string {
  return Number.isFinite(x) ? String(Number(x.toPrecision(digits))) : '—';
}
