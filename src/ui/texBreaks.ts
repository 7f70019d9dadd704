/**
 * Where a long inline or display formula may wrap. KaTeX lets a line break after every relation or
 * binary operator at the top level of a formula, also inside plain parentheses: on a phone,
 * "(x + 2)²" could end a line with "(x +". Wrapping each top-level parenthesized group that holds
 * an operator in braces makes it one atom, so lines break only at the operators outside
 * parentheses (and the group's own spacing is unchanged).
 */

/** A delimiter sized by \left, \right or \big… is part of that command, not a plain parenthesis. */
const SIZED = /\\(?:left|right|[bB]igg?[lrm]?)\s*$/;
/** An operator KaTeX would break after (written as a character or as a command). */
const BREAKING =
  /[+\-=<>−±∓≤≥≈≠·×→∈]|\\(?:cdot|times|pm|mp|le|ge|leq|geq|lt|gt|approx|ne|neq|to|in|notin|equiv|sim|simeq|propto|cup|cap|setminus|mid|ll|gg)(?![a-zA-Z])/;
/** Content a brace group cannot hold: alignment, row breaks, environments. */
const UNGROUPABLE = /&|\\\\|\\begin|\\end/;

export function keepParenthesesTogether(tex: string): string {
  // positions of the top-level (brace depth 0) plain parenthesis pairs
  const pairs: [number, number][] = [];
  const open: number[] = [];
  let depth = 0;
  for (let i = 0; i < tex.length; i++) {
    const ch = tex[i];
    if (ch === '\\') {
      // a control symbol (\{, \}, \(, \\ …) or a control word: never a brace or a parenthesis
      i++;
      while (i + 1 < tex.length && /[a-zA-Z]/.test(tex[i]) && /[a-zA-Z]/.test(tex[i + 1])) i++;
      continue;
    }
    if (ch === '{') depth++;
    else if (ch === '}') depth = Math.max(0, depth - 1);
    else if (depth === 0 && (ch === '(' || ch === ')') && !SIZED.test(tex.slice(Math.max(0, i - 8), i))) {
      if (ch === '(') open.push(i);
      else if (open.length) {
        const start = open.pop()!;
        // only the outermost pairs (an inner pair is already inside its outer group)
        if (open.length === 0) pairs.push([start, i]);
      }
    }
  }
  if (pairs.length === 0) return tex;
  let out = '';
  let last = 0;
  for (const [a, b] of pairs) {
    const inner = tex.slice(a + 1, b);
    if (!BREAKING.test(inner) || UNGROUPABLE.test(inner)) continue;
    out += `${tex.slice(last, a)}{${tex.slice(a, b + 1)}}`;
    last = b + 1;
  }
  return out + tex.slice(last);
}

/**
 * The outermost parenthesized groups of a plain-text formula ("3(x + 2)²/56", "4a(r² − |ℓ|²)") that
 * hold an operator and no word (a remark in prose wraps like prose), as [index of "(", index of ")"].
 */
export function textFormulaGroups(text: string): [number, number][] {
  const groups: [number, number][] = [];
  const open: number[] = [];
  for (let i = 0; i < text.length; i++) {
    if (text[i] === '(') open.push(i);
    else if (text[i] === ')' && open.length) {
      const a = open.pop()!;
      const inner = text.slice(a, i);
      if (open.length === 0 && TEXT_OPERATOR.test(inner) && !PROSE.test(inner)) groups.push([a, i]);
    }
  }
  return groups;
}

/**
 * The same as {@link keepParenthesesTogether} for a formula written as plain text: the spaces inside
 * each of its {@link textFormulaGroups} become no-break spaces, so the line wraps only outside them.
 */
export function keepTextParenthesesTogether(text: string): string {
  const out = text.split('');
  for (const [a, b] of textFormulaGroups(text)) {
    for (let j = a + 1; j < b; j++) if (out[j] === ' ') out[j] = '\u00a0';
  }
  return out.join('');
}

/** An operator in a plain-text formula (not a hyphen inside a word). */
const TEXT_OPERATOR = /\s[=+−×·<>≤≥≈≠∓±/]\s|[²³√∫Σ]/;
/** A word: the parentheses hold a remark in prose, which may wrap like any prose. */
const PROSE = /\p{L}{4,}/u;
