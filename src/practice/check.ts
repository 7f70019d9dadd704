/**
 * Checking a student's answers the way a careful grader would (STACK / PrairieLearn / WeBWorK style).
 *
 * Numbers ({@link NUMERIC_POLICY}): a plain number or an arithmetic expression of constants
 * (`56/3`, `2/(e^(2*pi)-1)`, `sqrt(2)/2`), read by the app's whitelisted expression compiler.
 * An answer x is correct when |x − e| ≤ 0.5 % of |e| (so any correct rounding to 3 significant
 * figures passes, and so does the exact value), or |x| ≤ 10⁻⁶ when e = 0. "none" answers a
 * quantity that does not exist (no root, no hit).
 *
 * Formulas ({@link FORMULA_POLICY}): mathjs syntax in the question's variable, compiled by the same
 * whitelisted compiler the scenes use (src/core/expr), and compared with the expected formula at
 * 40 seeded random points of the open domain (WeBWorK's method): equivalent when every point agrees
 * to 10⁻⁶ relative. Points where the expected formula is not finite are skipped; a student formula
 * that is not finite where the expected one is fails.
 *
 * Order of recognition: correct, then an accepted convention (correct, with a note), then a
 * classic mistake (its id), else incorrect. Generators drop any mistake whose value is within
 * {@link SEPARATION} tolerances of the correct answer, an accepted convention, or another mistake,
 * so a correct answer can never be classed as a mistake.
 */
import { compileExpression } from '../core/expr';
import { Rng } from '../core/random';
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

export const NUMERIC_POLICY = {
  /** Relative tolerance: half a unit in the third significant figure (worst case). */
  rtol: 0.005,
  /** Absolute tolerance when the expected value is exactly 0. */
  zeroTol: 1e-6,
  text: 'Numbers: type a number or an arithmetic expression such as 56/3 or 2*pi. An answer within 0.5 % of the exact value is correct, so 3 significant figures are enough (give more if you have them). Type none where a quantity does not exist.',
} as const;

export const FORMULA_POLICY = {
  points: 40,
  rtol: 1e-6,
  text: 'Formulas: type them in mathjs syntax, e.g. 2*sin(theta)*cos(theta), (1 - cos(2*theta))/2, acos(1 - 2*xi)/2, log(1 + (e^(2*pi) - 1)*xi). Use theta, phi and xi (θ, φ, ξ, ξ₁, ξ₂ work too; ln means log). A formula is correct when it equals the expected one at 40 random points of the domain (to 6 digits) — any equivalent form is accepted.',
} as const;

/** Mistakes closer than this many tolerances to a correct value are dropped by the generators. */
export const SEPARATION = 4;

/** What a verdict's data-value says. */
export type VerdictValue = 'correct' | 'incorrect' | 'invalid' | `mistake:${string}`;

export interface Verdict {
  value: VerdictValue;
  message: string;
}

// ---------------------------------------------------------------------------------------------
// Numbers

/** Tolerance around an expected value (see {@link NUMERIC_POLICY}). */
export function tolerance(e: number): number {
  return e === 0 ? NUMERIC_POLICY.zeroTol : NUMERIC_POLICY.rtol * Math.abs(e);
}

/** Whether x passes for e (null means "none"). */
export function numbersMatch(x: number | null, e: number | null): boolean {
  if (e === null || x === null) return e === x;
  return Math.abs(x - e) <= tolerance(e);
}

/** Clearly different: farther apart than {@link SEPARATION} tolerances of either value. */
export function numbersSeparated(a: number | null, b: number | null): boolean {
  if (a === null || b === null) return a !== b;
  return Math.abs(a - b) > SEPARATION * Math.max(tolerance(a), tolerance(b));
}

const PLAIN_NUMBER = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;
const NONE_WORDS = new Set([
  'none',
  'no',
  'n/a',
  'na',
  'nan',
  '-',
  '—',
  'no root',
  'no hit',
  'undefined',
  'does not exist',
]);

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

export type ParsedNumber = { ok: true; value: number | null } | { ok: false; error: string };

/** Read a numeric answer: a number, "none", or an expression of constants. Never throws. */
export async function parseNumberAnswer(text: string): Promise<ParsedNumber> {
  const raw = text.trim();
  if (raw === '') return { ok: false, error: 'Type a number (or none).' };
  if (raw.length > 200) return { ok: false, error: 'That answer is too long for a number.' };
  if (NONE_WORDS.has(raw.toLowerCase())) return { ok: true, value: null };
  const s = normaliseInput(raw);
  if (PLAIN_NUMBER.test(s)) {
    const x = Number(s);
    return Number.isFinite(x) ? { ok: true, value: x } : { ok: false, error: 'That number is too large.' };
  }
  if (/^[+-]?\d+,\d+$/.test(s))
    return { ok: false, error: `Use a decimal point, not a comma: ${s.replace(',', '.')}.` };
  const r = await compileExpression(s, []);
  if (!r.ok) return { ok: false, error: `Not a number: ${r.message}.` };
  const x = r.fn();
  if (!Number.isFinite(x)) return { ok: false, error: 'That expression has no finite value.' };
  return { ok: true, value: x };
}

/** Verdict of a numeric answer (see the module comment). */
export async function checkNumber(spec: NumberAnswer, text: string): Promise<Verdict> {
  const p = await parseNumberAnswer(text);
  if (!p.ok) return { value: 'invalid', message: p.error };
  return classifyNumber(spec, p.value);
}

/** The verdict for an already-read value (pure; used by the tests on every generated variant). */
export function classifyNumber(spec: NumberAnswer, x: number | null): Verdict {
  if (numbersMatch(x, spec.expected)) return { value: 'correct', message: 'Correct.' };
  for (const a of spec.alternatives)
    if (numbersMatch(x, a.value)) return { value: 'correct', message: `Correct — ${a.message}` };
  for (const m of spec.mistakes)
    if (numbersMatch(x, m.value)) return { value: `mistake:${m.id}`, message: m.message };
  if (spec.expected === null)
    return { value: 'incorrect', message: 'Not right: this quantity does not exist here (answer none).' };
  if (x === null) return { value: 'incorrect', message: 'Not right: this quantity exists; give its value.' };
  return { value: 'incorrect', message: 'Not right. Check each step against the worked solution.' };
}

/**
 * Keep the mistakes and conventions that a grader can tell apart: finite, clearly separated from
 * the correct answer, from the accepted conventions and from the mistakes kept before them.
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
    message: 'Not equivalent to the expected formula (it differs at some points of the domain).',
  };
}

/** Verdict of a typed formula: compiled by the whitelisted expression compiler, then compared. */
export async function checkFormula(spec: FormulaAnswer, text: string): Promise<Verdict> {
  const raw = text.trim();
  if (raw === '') return { value: 'invalid', message: `Type a formula in ${spec.variables.join(', ')}.` };
  const r = await compileExpression(normaliseInput(raw), spec.variables);
  if (!r.ok) return { value: 'invalid', message: `Cannot read that formula: ${r.message}.` };
  return classifyFormula(spec, r.fn);
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
