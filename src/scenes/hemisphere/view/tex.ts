/** A number for KaTeX: formatNumber's text with its "×10⁻³" turned into "\times 10^{-3}". */
import { formatNumber } from '../../../ui';

const SUP: Record<string, string> = {
  '⁻': '-',
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
};

export function texNum(x: number, digits = 6): string {
  if (!Number.isFinite(x)) return x > 0 ? '\\infty' : x < 0 ? '-\\infty' : '\\text{—}';
  const s = formatNumber(x, digits);
  const i = s.indexOf('×10');
  if (i < 0) return s;
  const exp = [...s.slice(i + 3)].map((c) => SUP[c] ?? c).join('');
  return `${s.slice(0, i)}\\times 10^{${exp}}`;
}
