import { Fragment, type ReactNode } from 'react';
import { keepTextParenthesesTogether } from './texBreaks';

/** A piece of plain text: words, or a power to be set as a superscript. */
export type CaretPart = string | { sup: CaretPart[] };

/** Characters that end a bare power such as the 3 of "cos^3 θ" or the φ of "e^φ". */
const BARE_END = /[\s)\]},.;:]/;

/**
 * Plain text with powers written the way one types them ("e^(2πa) − 1", "cos^3 θ", "e^φ",
 * "(1 − ξ₁)^(1/(m+1))") split into its words and its powers: a `^` followed by a parenthesised or
 * braced group takes the group's inside, else it takes the run up to a space or closing mark.
 * A caret with nothing after it stays as it is; powers of powers nest.
 */
export function caretParts(text: string): CaretPart[] {
  const out: CaretPart[] = [];
  let plain = '';
  let i = 0;
  while (i < text.length) {
    const ch = text[i];
    if (ch !== '^' || i + 1 >= text.length || /\s/.test(text[i + 1])) {
      plain += ch;
      i++;
      continue;
    }
    let j = i + 1;
    let inner: string;
    const open = text[j];
    if (open === '(' || open === '{') {
      const close = open === '(' ? ')' : '}';
      let depth = 0;
      for (; j < text.length; j++) {
        if (text[j] === open) depth++;
        else if (text[j] === close && --depth === 0) break;
      }
      if (j >= text.length) {
        // unbalanced: not a power we can read; keep the text
        plain += ch;
        i++;
        continue;
      }
      inner = text.slice(i + 2, j);
      j++;
    } else {
      while (j < text.length && !BARE_END.test(text[j]) && text[j] !== '^') j++;
      inner = text.slice(i + 1, j);
    }
    if (plain) out.push(plain);
    plain = '';
    out.push({ sup: caretParts(inner) });
    i = j;
  }
  if (plain) out.push(plain);
  return out;
}

function render(parts: CaretPart[]): ReactNode {
  return parts.map((p, k) =>
    typeof p === 'string' ? (
      <Fragment key={k}>{p}</Fragment>
    ) : (
      <Fragment key={k}>
        <span className="sr-only"> to the power </span>
        <sup>{render(p.sup)}</sup>
        <span className="sr-only">, </span>
      </Fragment>
    ),
  );
}

/**
 * Plain text (a question, a hint, a feedback message) with its typed powers set as superscripts,
 * so no reader sees a caret; a screen reader hears "to the power" before each one.
 */
export function Superscripted({ text }: { text: string }) {
  return <>{render(caretParts(keepTextParenthesesTogether(text)))}</>;
}
