/** TeX → MathML (the `<math>` element alone) with KaTeX, for QTI items; TeX as text on failure. */
import type { TexToMathml } from './banks';
import { xmlEscape } from './gaps';

interface KatexLike {
  renderToString(tex: string, options: Record<string, unknown>): string;
}

export function katexMathml(katex: KatexLike): TexToMathml {
  return (tex, display) => {
    try {
      const s = katex.renderToString(tex, { output: 'mathml', displayMode: display, throwOnError: true });
      const a = s.indexOf('<math');
      const b = s.lastIndexOf('</math>');
      if (a >= 0 && b > a) {
        const m = s.slice(a, b + '</math>'.length);
        return display ? `<div>${m}</div>` : m;
      }
    } catch {
      /* fall through to the TeX text */
    }
    return `<code>${xmlEscape(tex)}</code>`;
  };
}
