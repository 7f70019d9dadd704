/**
 * Checking a student's answers the way a careful grader would (STACK / PrairieLearn / WeBWorK style).
 *
 * Numbers ({@link NUMERIC_POLICY}): a decimal, or an arithmetic expression of constants (`56/3`,
 * `2/(e^(2*pi)-1)`, `sqrt(2)/2`) read by the app's whitelisted expression compiler. An expression is
 * compared exactly (10⁻⁹ relative): a near miss such as 3/e^(3π) for 3/(e^(3π) − 1) is never
 * correct. A decimal is compared at the precision it was typed to, as STACK's significant-figure
 * tests do: it must be the answer rounded to its last digit (half a unit there), with at least 3
 * significant figures. "none" answers a quantity that does not exist (no root, no hit).
 *
 * Formulas ({@link FORMULA_POLICY}): mathjs syntax in the question's variable, compiled by the same
 * whitelisted compiler the scenes use (src/core/expr), and compared with the expected formula at
 * 40 seeded random points of the open domain (WeBWorK's method): equivalent when every point agrees
 * to 10⁻⁸ relative. Points where the expected formula is not finite are skipped; a student formula
 * that is not finite where the expected one is fails.
 *
 * Recognition: the correct answer, an accepted convention (correct, with a note) or a classic
 * mistake (its id), else incorrect. Generators drop any mistake no typed text could tell apart from
 * the correct answer, an accepted convention or another mistake ({@link SEPARATION_RTOL}), so a
 * correct answer typed exactly is never classed as a mistake, nor a mistake typed exactly as correct.
 */
import { compileExpression } from '../core/expr';
import { Rng } from '../core/random';
import { decimalPrecision, nudgeConstants, withinConstantPrecision } from './decimals';
import type {
  AnswerSpec,
  ChoiceAnswer,
  FormulaAlternative,
  FormulaAnswer,
  FormulaMistake,
  Fn,
  NumberAlternative,
  NumberAnswer,
  NumberMistake,
} from './model';

/** (The policies' `text`: what is typed stands between backticks, shown as code.) */
export const NUMERIC_POLICY = {
  /** An exact expression (56/3, 2/(e^(2*pi) - 1)) must agree to this relative tolerance. */
  exactRtol: 1e-9,
  /** Absolute floor of the exact comparison (for answers that are exactly 0). */
  exactAtol: 1e-15,
  /** A typed decimal that is not exact needs at least this many significant figures. */
  minSigFigs: 3,
  text: 'Numbers: type a decimal (`0.00374`, `3.74e-3`) or an exact expression (`56/3`, `2/(e^(2*pi) - 1)`, `sqrt(2)/2`). An expression must be exactly right (to 9 digits). A decimal is read at the precision you typed it: 0.00374 means 0.003735 to 0.003745, so it must be the right answer rounded to the figures you give, with at least 3 significant figures. A value that is a classic mistake rather than the right answer is named as that mistake; if, to the figures you typed, it is both, it is marked correct with a note to give more figures. Type none where a quantity does not exist.',
} as const;

export const FORMULA_POLICY = {
  points: 40,
  rtol: 1e-8,
  text: 'Formulas: type them in mathjs syntax, e.g. `2*sin(theta)*cos(theta)`, `(1 - cos(2*theta))/2`, `acos(1 - 2*xi)/2`, `log(1 + (e^(2*pi) - 1)*xi)`. Use theta, phi and xi (θ, φ, ξ, ξ₁, ξ₂ work too; ln means log). A formula is correct when it equals the expected one at 40 random points of the domain (to 8 digits): any equivalent form is accepted. A decimal constant in a formula (`0.00187*exp(phi)`) is read at the precision you typed it, as a number is: the formula must be right with the constant rounded to the figures you give, with at least 3 significant figures (fewer is not marked wrong: you are asked for more).',
} as const;

/**
 * Mistakes and conventions whose values differ from the correct answer (and from each other) by
 * less than this relative amount are dropped by the generators: no typed text could tell them apart.
 */
export const SEPARATION_RTOL = 1e-7;

/** What a verdict's data-value says. */
export type VerdictValue = 'correct' | 'incorrect' | 'invalid' | 'consistent' | `mistake:${string}`;

export interface Verdict {
  value: VerdictValue;
  message: string;
  /**
   * The accepted convention the answer used (e.g. 'v-flip'), when it was correct only under it;
   * a variant's parts must use one convention throughout.
   */
  convention?: string;
  /** For `consistent`: the earlier answers (names) this one follows through from. */
  from?: string[];
}

// ---------------------------------------------------------------------------------------------
// Numbers

/** A number as typed: its value, and how precisely it was given. */
export interface TypedNumber {
  /** null: "none". */
  value: number | null;
  /** true for an expression or for a value given in full (the exact comparison applies). */
  exact: boolean;
  /** Half a unit in the last typed digit (decimals only). */
  halfUnit: number;
  /** Significant figures as typed (decimals only; Infinity for an exact value). */
  sigFigs: number;
  /** What was typed (for messages). */
  text: string;
}

/** An exact typed value (what the tests and the pure classifier use). */
export function exactNumber(x: number | null): TypedNumber {
  return { value: x, exact: true, halfUnit: 0, sigFigs: Infinity, text: x === null ? 'none' : String(x) };
}

/** Tolerance of the exact comparison around e. */
export function exactTolerance(e: number): number {
  return Math.max(NUMERIC_POLICY.exactRtol * Math.abs(e), NUMERIC_POLICY.exactAtol);
}

/** Whether x equals e exactly, in the sense of {@link NUMERIC_POLICY} (null means "none"). */
export function numbersMatch(x: number | null, e: number | null): boolean {
  if (e === null || x === null) return e === x;
  return Math.abs(x - e) <= exactTolerance(e);
}

/** Clearly different: no text could be both (relative {@link SEPARATION_RTOL}). */
export function numbersSeparated(a: number | null, b: number | null): boolean {
  if (a === null || b === null) return a !== b;
  return (
    Math.abs(a - b) >
    SEPARATION_RTOL * Math.max(Math.abs(a), Math.abs(b), 1e-300) + 2 * NUMERIC_POLICY.exactAtol
  );
}

const PLAIN_NUMBER = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;
const NONE_WORDS = new Set(['none', 'no', 'n/a', 'na', 'no root', 'no hit', 'does not exist']);
/**
 * Texts that say nothing a grader could read: a program's "not a number" or "undefined", or a bare
 * dash. They are unreadable answers (never "none": typing NaN in every box must not score).
 */
const UNREADABLE = /^(?:nan|[+-]?infinity|undefined|null|[-–—−]+)$/i;

/** Normalise what people type: unicode operators, ln, arc-functions, ξ₁/ξ₂ → xi. */
export function normaliseInput(s: string): string {
  return s
    .replace(/[−–]/g, '-')
    .replace(/[×·⋅]/g, '*')
    .replace(/÷/g, '/')
    .replace(/√/g, 'sqrt')
    .replace(/ξ\s*[₁₂12]?/g, 'xi')
    .replace(/\bxi[12]\b/g, 'xi')
    .replace(/\bln\s*\(/g, 'log(')
    .replace(/\barccos\b/g, 'acos')
    .replace(/\barcsin\b/g, 'asin')
    .replace(/\barctan\b/g, 'atan')
    .trim();
}

export type ParsedNumber = ({ ok: true } & TypedNumber) | { ok: false; error: string };

/** Read a numeric answer: a decimal, "none", or an expression of constants. Never throws. */
export async function parseNumberAnswer(text: string): Promise<ParsedNumber> {
  const raw = text.trim();
  if (raw === '') return { ok: false, error: 'Type a number (or none).' };
  if (raw.length > 200) return { ok: false, error: 'That answer is too long for a number.' };
  if (NONE_WORDS.has(raw.toLowerCase())) return { ok: true, ...exactNumber(null), text: raw };
  if (UNREADABLE.test(raw))
    return {
      ok: false,
      error: `“${raw}” is not an answer: type a number, or none where the quantity does not exist.`,
    };
  const s = normaliseInput(raw);
  if (PLAIN_NUMBER.test(s)) {
    const x = Number(s);
    if (!Number.isFinite(x)) return { ok: false, error: 'That number is too large.' };
    const p = decimalPrecision(s);
    return { ok: true, value: x + 0, exact: false, halfUnit: p.halfUnit, sigFigs: p.sigFigs, text: raw };
  }
  if (/^[+-]?\d+,\d+$/.test(s))
    return { ok: false, error: `Use a decimal point, not a comma: ${s.replace(',', '.')}.` };
  const r = await compileExpression(s, []);
  if (!r.ok) return { ok: false, error: `Not a number: ${r.message}.` };
  const x = r.fn();
  if (!Number.isFinite(x)) return { ok: false, error: 'That expression has no finite value.' };
  return { ok: true, ...exactNumber(x), text: raw };
}

/** Verdict of a numeric answer (see the module comment). */
export async function checkNumber(spec: NumberAnswer, text: string): Promise<Verdict> {
  const p = await parseNumberAnswer(text);
  if (!p.ok) return { value: 'invalid', message: p.error };
  return classifyTyped(spec, p);
}

/** The verdict for an exact value (pure; used by the tests on every generated variant). */
export function classifyNumber(spec: NumberAnswer, x: number | null): Verdict {
  return classifyTyped(spec, exactNumber(x));
}

interface Candidate {
  kind: 'correct' | 'alternative' | 'mistake';
  value: number | null;
  alt?: NumberAlternative;
  mistake?: NumberMistake;
}

function candidates(spec: NumberAnswer): Candidate[] {
  return [
    { kind: 'correct', value: spec.expected },
    ...spec.alternatives.map((a): Candidate => ({ kind: 'alternative', value: a.value, alt: a })),
    ...spec.mistakes.map((m): Candidate => ({ kind: 'mistake', value: m.value, mistake: m })),
  ];
}

function verdictOf(c: Candidate, note = ''): Verdict {
  if (c.kind === 'correct') return { value: 'correct', message: `Correct.${note}` };
  if (c.kind === 'alternative')
    return {
      value: 'correct',
      message: `Correct: ${c.alt!.message}${note}`,
      ...(c.alt!.convention ? { convention: c.alt!.convention } : {}),
    };
  return { value: `mistake:${c.mistake!.id}`, message: c.mistake!.message };
}

/**
 * The verdict for a typed value. An exact value is compared exactly with the correct answer, the
 * accepted conventions and the named mistakes. A decimal is compared at the precision it was typed
 * to: it "is" every value it is a correct rounding of. Of those, the correct answer (or an accepted
 * convention) wins, with a note when a named mistake rounds to the same figures; otherwise the
 * nearest named mistake is named.
 */
export function classifyTyped(spec: NumberAnswer, t: TypedNumber): Verdict {
  const cs = candidates(spec);
  const x = t.value;
  if (x === null || t.exact) {
    for (const c of cs) if (numbersMatch(x, c.value)) return verdictOf(c);
  } else {
    const h = t.halfUnit * (1 + 1e-9) + exactTolerance(x);
    const within = cs
      .filter((c) => c.value !== null && Math.abs(x - c.value) <= h)
      .sort((p, q) => Math.abs(x - p.value!) - Math.abs(x - q.value!));
    const right = within.find((c) => c.kind !== 'mistake');
    if (t.sigFigs < NUMERIC_POLICY.minSigFigs) {
      // too few figures to be read at their precision: only a value typed in full counts
      const same = cs.find((c) => numbersMatch(x, c.value));
      if (same) return verdictOf(same);
    }
    if (right && t.sigFigs < NUMERIC_POLICY.minSigFigs)
      return {
        value: 'invalid',
        message: `${t.text} has ${t.sigFigs} significant figure${t.sigFigs === 1 ? '' : 's'}: give at least ${NUMERIC_POLICY.minSigFigs}, or an exact expression.`,
      };
    if (right) {
      const also = within.find((c) => c.kind === 'mistake');
      return verdictOf(
        right,
        also
          ? ` (To the figures you typed, this is also what the mistake “${also.mistake!.id}” gives; more figures would tell them apart.)`
          : '',
      );
    }
    if (within.length) return verdictOf(within[0]);
  }
  if (spec.expected === null)
    return { value: 'incorrect', message: 'Not right: this quantity does not exist here (answer none).' };
  if (x === null) return { value: 'incorrect', message: 'Not right: this quantity exists; give its value.' };
  if (!t.exact && Math.abs(x - spec.expected) <= 0.01 * Math.abs(spec.expected))
    return {
      value: 'incorrect',
      message: `Close, but not right to the figures you typed: ${t.text} is not the answer rounded to that precision. Check your rounding, or type more figures.`,
    };
  return {
    value: 'incorrect',
    message:
      'Not right, and not one of the classic mistakes: redo this step (the part’s hint gives its first step).',
  };
}

/**
 * Keep the mistakes and conventions that a grader can tell apart: finite, separated from the
 * correct answer, from the accepted conventions and from the mistakes kept before them.
 */
export function separateNumbers(
  expected: number | null,
  alternatives: NumberAlternative[],
  mistakes: { id: string; value: number | null; message: string }[],
): { alternatives: NumberAlternative[]; mistakes: NumberMistake[] } {
  const keptAlt: NumberAlternative[] = [];
  for (const a of alternatives) {
    if (!Number.isFinite(a.value)) continue;
    if (!numbersSeparated(a.value, expected)) continue; // same as the correct answer: nothing to say
    if (keptAlt.some((k) => !numbersSeparated(k.value, a.value))) continue;
    keptAlt.push(a);
  }
  const kept: NumberMistake[] = [];
  for (const m of mistakes) {
    if (m.value === null || !Number.isFinite(m.value)) continue;
    const v = m.value;
    if (!numbersSeparated(v, expected)) continue;
    if (keptAlt.some((a) => !numbersSeparated(a.value, v))) continue;
    if (kept.some((k) => !numbersSeparated(k.value, v))) continue;
    kept.push({ id: m.id, value: v, message: m.message });
  }
  return { alternatives: keptAlt, mistakes: kept };
}

// ---------------------------------------------------------------------------------------------
// Formulas

const POINT_SEED = 0x5eed_f0a1;

/** The comparison points of a domain (seeded: the same points every time). */
export function formulaPoints(
  domain: readonly (readonly [number, number])[],
  count: number = FORMULA_POLICY.points,
): number[][] {
  const rng = new Rng(POINT_SEED, domain.length);
  const pts: number[][] = [];
  for (let k = 0; k < count; k++) {
    pts.push(
      domain.map(([lo, hi]) => {
        const w = hi - lo;
        return lo + w * (0.01 + 0.98 * rng.nextFloat());
      }),
    );
  }
  return pts;
}

/**
 * Whether g equals f at every comparison point (relative 10⁻⁶, with an absolute floor of 10⁻⁹ of
 * f's largest magnitude there). Points where f is not finite are skipped; at least half must remain.
 */
export function formulasEquivalent(f: Fn, g: Fn, domain: readonly (readonly [number, number])[]): boolean {
  const pts = formulaPoints(domain);
  const fv: number[] = [];
  let scale = 0;
  for (const p of pts) {
    const y = f(...p);
    fv.push(y);
    if (Number.isFinite(y)) scale = Math.max(scale, Math.abs(y));
  }
  let used = 0;
  for (let k = 0; k < pts.length; k++) {
    const e = fv[k];
    if (!Number.isFinite(e)) continue;
    const s = g(...pts[k]);
    if (!Number.isFinite(s)) return false;
    const tol = FORMULA_POLICY.rtol * Math.max(Math.abs(e), 1e-3 * scale) + 1e-300;
    if (Math.abs(s - e) > tol) return false;
    used++;
  }
  return used >= pts.length / 2;
}

/** Verdict of a formula, given its compiled function (pure). */
export function classifyFormula(spec: FormulaAnswer, g: Fn): Verdict {
  if (formulasEquivalent(spec.expected, g, spec.domain)) return { value: 'correct', message: 'Correct.' };
  for (const a of spec.alternatives)
    if (formulasEquivalent(a.fn, g, spec.domain))
      return { value: 'correct', message: `Correct — ${a.message}` };
  for (const m of spec.mistakes)
    for (const fn of m.fns)
      if (formulasEquivalent(fn, g, spec.domain)) return { value: `mistake:${m.id}`, message: m.message };
  return {
    value: 'incorrect',
    message:
      'Not equivalent to the expected formula (it differs at some points of the domain), and not one of the classic mistakes: the part’s hint gives the first step.',
  };
}

/**
 * Verdict of a typed formula (normalised text, compiled function): {@link classifyFormula}, else its
 * rounded decimal constants read at their precision as a number is (right to the figures typed is
 * correct; with under 3 significant figures more are asked for, not graded; a named mistake is named).
 */
export async function classifyTypedFormula(spec: FormulaAnswer, text: string, g: Fn): Promise<Verdict> {
  const exact = classifyFormula(spec, g);
  const nudges = exact.value === 'incorrect' ? await nudgeConstants(text, spec.variables) : null;
  if (!nudges) return exact;
  const pts = formulaPoints(spec.domain);
  const near = (f: Fn) => withinConstantPrecision(f, g, nudges, pts, FORMULA_POLICY.rtol);
  const alt = near(spec.expected) ? null : spec.alternatives.find((a) => near(a.fn));
  if (near(spec.expected) || alt) {
    const few = nudges.constants.find((c) => c.sigFigs < NUMERIC_POLICY.minSigFigs);
    const fig = `${few?.sigFigs} significant figure${few?.sigFigs === 1 ? '' : 's'}`;
    const say = few ? `The constant ${few.text} has ${fig}: give at least 3, or write it exactly.` : '';
    if (few) return { value: 'invalid', message: say };
    const note = alt ? ` — ${alt.message}` : '.';
    return { value: 'correct', message: `Correct to the figures of its constants${note}` };
  }
  const m = spec.mistakes.find((x) => x.fns.some(near));
  return m ? { value: `mistake:${m.id}`, message: m.message } : exact;
}

/** Verdict of a typed formula: compiled by the whitelisted expression compiler, then compared. */
export async function checkFormula(spec: FormulaAnswer, text: string): Promise<Verdict> {
  const raw = text.trim();
  if (raw === '') return { value: 'invalid', message: `Type a formula in ${spec.variables.join(', ')}.` };
  const src = normaliseInput(raw);
  const r = await compileExpression(src, spec.variables);
  if (!r.ok) return { value: 'invalid', message: `Cannot read that formula: ${r.message}.` };
  return classifyTypedFormula(spec, src, r.fn);
}

/** Drop formula conventions and mistakes that are equivalent to the correct answer or to each other. */
export function separateFormulas(
  expected: Fn,
  domain: readonly (readonly [number, number])[],
  alternatives: FormulaAlternative[],
  mistakes: FormulaMistake[],
): { alternatives: FormulaAlternative[]; mistakes: FormulaMistake[] } {
  const alts = alternatives.filter((a) => !formulasEquivalent(expected, a.fn, domain));
  const seen: Fn[] = [expected, ...alts.map((a) => a.fn)];
  const kept: FormulaMistake[] = [];
  for (const m of mistakes) {
    const fns = m.fns.filter((fn) => {
      if (!formulasEquivalent(fn, fn, domain)) return false; // not finite on most of the domain: nobody types it
      if (seen.some((s) => formulasEquivalent(s, fn, domain) || formulasEquivalent(fn, s, domain)))
        return false;
      return true;
    });
    if (fns.length) {
      kept.push({ ...m, fns });
      seen.push(...fns);
    }
  }
  return { alternatives: alts, mistakes: kept };
}

// ---------------------------------------------------------------------------------------------
// Choices

export function checkChoice(spec: ChoiceAnswer, text: string): Verdict {
  const s = text.trim().toLowerCase().replace(/\s+/g, '-');
  if (s === '') return { value: 'invalid', message: `Choose one of: ${spec.options.join(', ')}.` };
  if (!spec.options.includes(s))
    return {
      value: 'invalid',
      message: `"${text.trim().slice(0, 24)}" is not one of: ${spec.options.join(', ')}.`,
    };
  if (s === spec.expected) return { value: 'correct', message: `Correct. ${spec.why}` };
  for (const m of spec.mistakes) if (m.value === s) return { value: `mistake:${m.id}`, message: m.message };
  return { value: 'incorrect', message: `Not right. ${spec.why}` };
}

/** Check any answer. Never throws. */
export async function checkAnswer(spec: AnswerSpec, text: string): Promise<Verdict> {
  try {
    if (spec.kind === 'number') return await checkNumber(spec, text);
    if (spec.kind === 'formula') return await checkFormula(spec, text);
    return checkChoice(spec, text);
  } catch (e) {
    return {
      value: 'invalid',
      message: `That answer could not be read (${e instanceof Error ? e.message : String(e)}).`,
    };
  }
}

/** The expected answer as the page prints it (and as a test can type it back). */
export function expectedText(spec: AnswerSpec): string {
  if (spec.kind === 'number') return spec.expected === null ? 'none' : String(spec.expected);
  if (spec.kind === 'formula') return spec.expectedText;
  return spec.expected;
}
