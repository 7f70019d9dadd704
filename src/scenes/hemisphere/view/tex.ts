/** A number for KaTeX: formatNumber's text with its "×10⁻³" turned into "\times 10^{-3}". */
import { formatNumber } from '../../../ui';
import { unsuperscript } from '../../../ui/axis';

export function texNum(x: number, digits = 6): string {
  if (!Number.isFinite(x)) return x > 0 ? '\\infty' : x < 0 ? '-\\infty' : '\\text{—}';
  const s = formatNumber(x, digits);
  const i = s.indexOf('×10');
  if (i < 0) return s;
  const exp = unsuperscript(s.slice(i + 3));
  return `${s.slice(0, i)}\\times 10^{${exp}}`;
}
