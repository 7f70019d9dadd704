/**
 * KaTeX's MathML, tidied for speech (the visible HTML is untouched): what screen readers and
 * MathML speech engines read of a formula.
 * - Spacing-only `<mtext>` (KaTeX writes `\!` and similar kerning as a thin space followed by an
 *   invisible separator) is dropped: speech engines read the separator as "comma" ("l n comma
 *   open bracket" for `\ln\!\big[`).
 * - A single upright capital Greek letter (TeX sets Δ, Ω upright; KaTeX marks it
 *   mathvariant="normal") loses the mark, so it is read "upper Delta", not "normal upper Delta".
 * Pure string work on KaTeX's own output; anything else is kept as it is.
 */

const SPACING_MTEXT = /<mtext>[\s\u00a0\u2000-\u200b\u205f\u2061-\u2064\u3000]*<\/mtext>/g;
const UPRIGHT_GREEK = /<mi mathvariant="normal">([\u0391-\u03a9])<\/mi>/g;

function tidy(math: string): string {
  return math.replace(SPACING_MTEXT, '').replace(UPRIGHT_GREEK, '<mi>$1</mi>');
}

/** KaTeX's HTML + MathML (or MathML only) with every `<math>…</math>` tidied for speech. */
export function speakableMathml(html: string): string {
  return html.replace(/<math\b[\s\S]*?<\/math>/g, tidy);
}
