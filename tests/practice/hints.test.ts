/**
 * A hint points the way without restating an answer the student has not earned yet: no hint
 * contains the expected answer of its own part or of an earlier part, as a value (to any of the
 * roundings the page prints) or as an expression (the key's TeX or the typed form).
 */
import { describe, expect, it } from 'vitest';
import { formatSignificant } from '../../src/core/format';
import { expectedText } from '../../src/practice/check';
import { tn, type AnswerSpec, type SolutionStep, type Variant } from '../../src/practice/model';
import { QUESTIONS } from '../../src/practice/questions';

const SEEDS = 40;

/** TeX and text without spacing commands, blanks and primes (θ′ reads as θ). */
function squash(s: string): string {
  return s.replace(/\\[,;:!]|\\q?quad|\\big|\\Big|\\left|\\right|\s|'|′/g, '');
}

/**
 * The numbers a text shows, without their signs (−b shows b), as written (a digit run with its
 * point and exponent). Vectors "(x, y, z)" are left out: they restate given or derived points.
 */
function numbersIn(s: string): Set<string> {
  const noVectors = s.replace(/\(\s*-?[\d.e-]+(?:\s*,\s*-?[\d.e-]+){2}\s*\)/g, ' ');
  return new Set([...noVectors.matchAll(/(?<![\d.])\d+(?:\.\d+)?(?:e-?\d+)?(?![\d.])/g)].map((m) => m[0]));
}

function stepsText(steps: readonly SolutionStep[]): string {
  return steps.map((s) => `${s.text ?? ''} ${s.tex ?? ''}`).join(' ');
}

/** The forms an answer can be read from in a hint. */
function answerForms(a: AnswerSpec): { numbers: string[]; expressions: string[] } {
  if (a.kind === 'number') {
    if (a.expected === null) return { numbers: [], expressions: [] };
    const x = a.expected;
    const ax = Math.abs(x);
    const ns = new Set([String(ax), tn(ax).replace(/ \\times 10\^\{(-?\d+)\}/, 'e$1')]);
    for (const d of [3, 4, 5, 6]) ns.add(formatSignificant(ax, d, 'e'));
    return { numbers: [...ns], expressions: [] };
  }
  if (a.kind === 'formula') {
    const rhs = a.tex ? a.tex.slice(a.tex.indexOf('=') + 1) : '';
    return { numbers: [], expressions: [squash(rhs), squash(expectedText(a))].filter((e) => e.length >= 12) };
  }
  return { numbers: [], expressions: [] };
}

/** Every place a hint restates an answer it should not. */
function leaks(v: Variant): string[] {
  const out: string[] = [];
  // what the question itself states may be restated freely
  const stated = numbersIn(`${v.statement} ${v.givens.map((g) => `${g.display} ${g.value}`).join(' ')}`);
  v.parts.forEach((part, i) => {
    const hint = stepsText(part.hint);
    const shown = numbersIn(`${hint} ${part.hint.map((s) => s.text ?? '').join(' ')}`);
    const flat = squash(hint);
    for (const earlier of v.parts.slice(0, i + 1))
      for (const a of earlier.answers) {
        const f = answerForms(a);
        for (const n of f.numbers)
          if (shown.has(n) && !stated.has(n) && Math.abs(Number(n)) > 2)
            out.push(`(${part.id}) hint shows ${a.name} = ${n}`);
        for (const e of f.expressions)
          if (flat.includes(e)) out.push(`(${part.id}) hint shows ${a.name} = ${e}`);
      }
  });
  return out;
}

describe('hints', () => {
  it.each(QUESTIONS.map((q) => [q.id, q] as const))(
    '%s: no hint restates the answer of its own or an earlier part',
    (_id, q) => {
      const found: string[] = [];
      for (let s = 0; s < SEEDS; s++) {
        const v = q.generate(s * 7919 + 13);
        found.push(...leaks(v).map((l) => `seed ${v.seed}: ${l}`));
      }
      expect(found.slice(0, 10)).toEqual([]);
    },
  );
});
