/**
 * A practice variant as the gaps of a question bank item (Moodle XML, QTI 2.1). A bank grades
 * what it can tell apart without the app's formula checker, so:
 *  - a number answer is a numeric gap with the tolerance the app allows the fewest figures it
 *    accepts ({@link bankTolerance}: the answer rounded to 3 significant figures passes, as it does
 *    on the practice page; a bank cannot see how many figures were typed, so more precise wrong
 *    values within that band pass too); accepted conventions are full-credit answers, each named
 *    mistake a no-credit answer with its message as feedback;
 *  - a number answer whose expected value is "none" is a text gap answered `none`;
 *  - a formula answer becomes the formula's value at a stated point of its domain (a numeric gap;
 *    the mistakes' formulas evaluated at the same point keep their feedback);
 *  - a choice is a choice gap.
 */
import { NUMERIC_POLICY, numbersSeparated } from '../practice/check';
import { formatSignificant } from '../core/format';
import { allAnswers, type AnswerSpec, type Variant } from '../practice/model';

export interface GapMistake {
  /** The named mistake (verdict `mistake:<id>`). */
  id: string;
  /** Its value (numeric gaps) or its option (choice gaps). */
  value: number | string;
  message: string;
}

export type Gap =
  | {
      kind: 'number';
      name: string;
      label: string;
      /** The prompt for this gap (a formula's gap names its point). */
      prompt: string;
      value: number;
      tol: number;
      /** Further full-credit values (accepted conventions). */
      alternatives: { value: number; message: string }[];
      mistakes: GapMistake[];
    }
  | { kind: 'none'; name: string; label: string; prompt: string; mistakes: GapMistake[] }
  | {
      kind: 'choice';
      name: string;
      label: string;
      prompt: string;
      options: readonly string[];
      expected: string;
      why: string;
      mistakes: GapMistake[];
    };

/**
 * Half a unit in the last of the fewest significant figures the practice checker accepts for a
 * typed decimal (NUMERIC_POLICY.minSigFigs = 3): 0.5 × 10^(⌊log₁₀|e|⌋ − 2); the exact floor at 0.
 */
export function bankTolerance(e: number): number {
  if (e === 0 || !Number.isFinite(e)) return NUMERIC_POLICY.exactAtol;
  const t = 0.5 * 10 ** (Math.floor(Math.log10(Math.abs(e))) - (NUMERIC_POLICY.minSigFigs - 1));
  return Number(t.toPrecision(6));
}

/** A round point inside the domain where the expected formula is finite. */
function formulaPoint(spec: Extract<AnswerSpec, { kind: 'formula' }>): number[] | null {
  for (const f of [0.3, 0.4, 0.6, 0.7, 0.2, 0.8]) {
    const p = spec.domain.map(([lo, hi]) => Number((lo + f * (hi - lo)).toPrecision(3)));
    const y = spec.expected(...p);
    if (Number.isFinite(y)) return p;
  }
  return null;
}

/**
 * Keep values that the bank's tolerance band can tell from every value kept before them (farther
 * apart than two bands, so no typed value is in both).
 */
function separated<T extends { value: number }>(first: number[], xs: T[]): T[] {
  const seen = [...first];
  const out: T[] = [];
  const apart = (a: number, b: number) =>
    numbersSeparated(a, b) && Math.abs(a - b) > bankTolerance(a) + bankTolerance(b);
  for (const x of xs) {
    if (!Number.isFinite(x.value) || seen.some((s) => !apart(s, x.value))) continue;
    seen.push(x.value);
    out.push(x);
  }
  return out;
}

export function gapOf(spec: AnswerSpec): Gap | null {
  if (spec.kind === 'choice')
    return {
      kind: 'choice',
      name: spec.name,
      label: spec.label,
      prompt: spec.label,
      options: spec.options,
      expected: spec.expected,
      why: spec.why,
      mistakes: spec.mistakes.map((m) => ({ id: m.id, value: m.value, message: m.message })),
    };
  if (spec.kind === 'number') {
    if (spec.expected === null)
      return {
        kind: 'none',
        name: spec.name,
        label: spec.label,
        prompt: `${spec.label} (type none if it does not exist)`,
        mistakes: [],
      };
    const alternatives = separated([spec.expected], spec.alternatives);
    return {
      kind: 'number',
      name: spec.name,
      label: spec.label,
      prompt: spec.label,
      value: spec.expected,
      tol: bankTolerance(spec.expected),
      alternatives,
      mistakes: separated(
        [spec.expected, ...alternatives.map((a) => a.value)],
        spec.mistakes.map((m) => ({ id: m.id, value: m.value, message: m.message })),
      ),
    };
  }
  const p = formulaPoint(spec);
  if (!p) return null;
  const value = spec.expected(...p);
  const at = spec.variables.map((v, i) => `${v} = ${formatSignificant(p[i], 6, 'e')}`).join(', ');
  const alternatives = separated(
    [value],
    spec.alternatives.map((a) => ({ value: a.fn(...p), message: a.message })),
  );
  const mistakes = separated(
    [value, ...alternatives.map((a) => a.value)],
    spec.mistakes.flatMap((m) => m.fns.map((fn) => ({ id: m.id, value: fn(...p), message: m.message }))),
  );
  return {
    kind: 'number',
    name: spec.name,
    label: spec.label,
    prompt: `${spec.label} at ${at} (the value of your formula there)`,
    value,
    tol: bankTolerance(value),
    alternatives,
    mistakes,
  };
}

/** Every gap of a variant (a formula with no finite point in its domain is left out). */
export function gapsOf(v: Variant): Gap[] {
  return allAnswers(v)
    .map(gapOf)
    .filter((g): g is Gap => g !== null);
}

/** A number for a bank file: up to 12 significant digits, no exponent where avoidable. */
export function num(x: number): string {
  if (x === 0) return '0';
  const s = Number(x.toPrecision(12)).toString();
  return s;
}

export function xmlEscape(s: string): string {
  return s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
}
