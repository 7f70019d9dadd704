/**
 * A plain-text reading of TeX, shown while a formula waits for KaTeX (./MathTex): "p(ω) = k cos θ
 * eᵠ" instead of the source "p(\omega) = k\cos\theta\,e^{\phi}". It reads better on a slow phone
 * and to a screen reader, and, being about as wide as the typeset formula, the text around it
 * moves less when the formula arrives (Lighthouse's layout shift).
 *
 * Two forms: {@link texPreviewParts}, what is shown (scripts in Unicode where it has every
 * character, else marked for <sup> / <sub>, so no caret is ever shown), and {@link texPreview}, one
 * string with "^" and "_" where Unicode lacks a digit's or sign's script ("e^φ"), the source of the
 * accessible name ({@link previewLabel} says the marks in words).
 *
 * One pass over the characters (no backtracking), never throws; what it does not know it keeps.
 */
import { SUPERSCRIPT } from '../core/format';
import { ACCENT, BIG_OP, DROP, NAMED_OPERATORS, SKIP_ARGS, SUB, SUP_SHOWN, SYMBOL } from './texSymbols';

/** Marks around a script Unicode cannot write (never in TeX source: control characters). */
const SUP_OPEN = '\u0001';
const SUB_OPEN = '\u0002';
const CLOSE = '\u0003';
const MARKS = new RegExp(`[${SUP_OPEN}${SUB_OPEN}${CLOSE}]`, 'g');

/** Longest input read; the rest is cut (a formula on a page is far shorter). */
const MAX_CHARS = 20_000;

/** The plain-text reading as one string; scripts Unicode cannot write are "^x", "_(ab)". */
export function texPreview(tex: string, display = false): string {
  const stack: string[] = [];
  let out = '';
  for (const ch of read(tex, display, SUPERSCRIPT)) {
    if (ch === SUP_OPEN || ch === SUB_OPEN) {
      stack.push(out, ch === SUP_OPEN ? '^' : '_');
      out = '';
    } else if (ch === CLOSE && stack.length) {
      const mark = stack.pop()!;
      out = stack.pop()! + mark + wrap(out);
    } else if (ch !== CLOSE) out += ch;
  }
  return out;
}

/** A piece of the shown reading: text, or a script to set in <sup> / <sub>. */
export type PreviewPart = string | { tag: 'sup' | 'sub'; parts: PreviewPart[] };

/** Scripts nested deeper than this are shown as their text, inline (hostile input only). */
const MAX_SCRIPT_DEPTH = 4;

/** The reading as shown: text and the scripts Unicode cannot write, to be set as <sup> / <sub>. */
export function texPreviewParts(tex: string, display = false): PreviewPart[] {
  const root: PreviewPart[] = [];
  const stack = [root];
  let text = '';
  const flush = () => {
    if (text) stack[stack.length - 1].push(text);
    text = '';
  };
  let depth = 0;
  for (const ch of read(tex, display, SUP_SHOWN)) {
    if (ch === SUP_OPEN || ch === SUB_OPEN) {
      if (++depth >= MAX_SCRIPT_DEPTH) continue;
      flush();
      const p: PreviewPart = { tag: ch === SUP_OPEN ? 'sup' : 'sub', parts: [] };
      stack[stack.length - 1].push(p);
      stack.push(p.parts);
    } else if (ch === CLOSE) {
      if (depth-- >= MAX_SCRIPT_DEPTH || depth < 0) continue;
      flush();
      stack.pop();
    } else text += ch;
  }
  flush();
  return root;
}

/** The reading with scripts Unicode cannot write (with `sup`'s characters) between marks. */
function read(tex: string, display: boolean, sup: Readonly<Record<string, string>>): string {
  // (the marks' characters, should the source hold any, are dropped)
  const s = (tex.length > MAX_CHARS ? tex.slice(0, MAX_CHARS) : tex).replace(MARKS, '');
  let i = 0;

  /** The group or single token starting at i (after spaces), read to plain text. */
  function argument(): string {
    while (s[i] === ' ') i++;
    if (i >= s.length) return '';
    if (s[i] === '{') {
      i++;
      return until('}');
    }
    if (s[i] === '\\') return command();
    return s[i++];
  }

  /** Skip an optional argument ([…]) at i, after spaces. */
  function skipOptional(): void {
    while (s[i] === ' ') i++;
    if (s[i] === '[') {
      const k = s.indexOf(']', i);
      i = k < 0 ? s.length : k + 1;
    }
  }

  /** A backslash command at i, read to plain text (consumes its arguments where it has some). */
  function command(): string {
    i++; // the backslash
    if (i >= s.length) return '';
    const c = s[i];
    if (!/[A-Za-z]/.test(c)) {
      i++;
      if (c === '\\') {
        // a row break, with its optional spacing ([4pt])
        if (s[i] === '[') skipOptional();
        return display ? '\n' : ' ';
      }
      return SYMBOL[c] ?? c;
    }
    let j = i;
    while (j < s.length && /[A-Za-z]/.test(s[j])) j++;
    const name = s.slice(i, j);
    i = j;
    if (name === 'frac' || name === 'dfrac' || name === 'tfrac' || name === 'cfrac') {
      const a = argument();
      const b = argument();
      return `${wrap(a)}/${wrap(b)}`;
    }
    if (name === 'sqrt') {
      skipOptional();
      return `√${wrap(argument())}`;
    }
    if (name === 'begin' || name === 'end') {
      argument(); // the environment's name
      while (s[i] === ' ') i++;
      if (name === 'begin' && s[i] === '{') argument(); // a column spec ({array}{cc})
      return '';
    }
    if (name in SKIP_ARGS) {
      // (the text that follows, a colour box's for one, is read as usual)
      const [count, reads] = SKIP_ARGS[name];
      for (let a = 0; a < count; a++) argument();
      return reads;
    }
    if (name === 'xrightarrow' || name === 'xleftarrow') {
      skipOptional();
      const over = argument().trim();
      const arrow = name === 'xrightarrow' ? '→' : '←';
      return over ? ` ${arrow}(${over}) ` : ` ${arrow} `;
    }
    if (name === 'newline' || name === 'linebreak') return display ? '\n' : ' ';
    if (NAMED_OPERATORS.has(name)) return ` ${name} `;
    if (name in ACCENT) {
      const a = argument();
      return [...a].length === 1 ? a + ACCENT[name] : a;
    }
    if (BIG_OP.has(name)) return ` ${SYMBOL[name]}`;
    if (name in SYMBOL) return SYMBOL[name];
    if (DROP.has(name)) return '';
    return name;
  }

  /** Read to plain text up to `end` (a closing brace) or the end of the input. */
  function until(end: '}' | null): string {
    let out = '';
    let depth = 0;
    while (i < s.length) {
      const c = s[i];
      if (c === '\\') out += command();
      else if (c === '{') {
        // a plain group: its braces go, without a call per level (hostile nesting)
        depth++;
        i++;
      } else if (c === '}') {
        i++;
        if (depth > 0) depth--;
        else if (end !== null) return out;
        // else unbalanced: dropped
      } else if (c === '^' || c === '_') {
        i++;
        const arg = argument();
        // a script belongs to what precedes it: no space between ("cosᵐθ", not "cos ᵐθ")
        while (out.endsWith(' ')) out = out.slice(0, -1);
        out += script(arg, c === '^' ? sup : SUB, c === '^' ? SUP_OPEN : SUB_OPEN);
      } else if (c === '&' || c === '~') {
        // a column break, a tie
        i++;
        out += ' ';
      } else {
        i++;
        out += c === '-' ? '−' : c;
      }
    }
    return out;
  }

  let text: string;
  try {
    text = until(null);
  } catch {
    // commands nested thousands deep ran out of stack: the source it is
    return s;
  }
  // tidy the spacing: no runs of spaces, none around line breaks, named operators not padded at
  // the ends or before punctuation
  return (
    text
      .replace(/[ \t]+/g, ' ')
      .replace(/ ?\n ?/g, '\n')
      .replace(/ ([,.;)\]}|])/g, '$1')
      .replace(/([([{|]) /g, '$1')
      // a norm's bars hug what they enclose (the odd pieces between ‖ … ‖)
      .split('‖')
      .map((piece, k, all) => (k % 2 === 1 && k < all.length - 1 ? piece.trim() : piece))
      .join('‖')
      .trim()
      .normalize('NFC')
  );
}

function wrap(t: string): string {
  const x = t.trim();
  return x.length <= 1 || /^[\w.′]+$/u.test(x) ? x : `(${x})`;
}

/** A script in Unicode when `map` has each of its characters, else between `open` and CLOSE. */
function script(arg: string, map: Readonly<Record<string, string>>, open: string): string {
  const x = arg.trim();
  if (x === '') return '';
  if (x === '′' || x === '′′') return x;
  let out = '';
  for (const ch of x) {
    const m = map[ch];
    if (m === undefined) return `${open}${x}${CLOSE}`;
    out += m;
  }
  return out;
}

/**
 * The accessible name of a formula's plain-text reading (shown until KaTeX has typeset it): the
 * text with the marks a screen reader would read as punctuation ("^", "_") said in words.
 */
export function previewLabel(preview: string): string {
  return preview.replace(/\^/g, ' to the power ').replace(/_/g, ' sub ').replace(/\s+/g, ' ').trim();
}
