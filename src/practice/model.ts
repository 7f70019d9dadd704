/**
 * Practice mode: the data every question variant is made of. A variant is a pure function of
 * (question, seed): its givens, the answers it asks for (each with the expected value, the
 * conventions the key also accepts, and the values the classic mistakes produce), the worked
 * solution in the key's form with the variant's own numbers, and a link to the matching scene.
 * Nothing here touches the DOM; the page (PracticeRoute.tsx) only renders and checks it.
 */
import { formatSignificant } from '../core/format';

export const QUESTION_IDS = ['q1', 'q2', 'q3', 'q4', 'q5', 'q6'] as const;
export type QuestionId = (typeof QUESTION_IDS)[number];

export function isQuestionId(s: string): s is QuestionId {
  return (QUESTION_IDS as readonly string[]).includes(s);
}

/** A function of the formula's variables (positional, in the order the answer lists them). */
export type Fn = (...x: number[]) => number;

/** A parameter the question states; `value` is the contract's full-precision `data-value`. */
export interface Given {
  name: string;
  label: string;
  /** data-value: String(x) for numbers, "x,y,z" for vectors, the grid text, expression text. */
  value: string;
  /** What the page prints (may be rounded; the data-value is not). */
  display: string;
  /** Optional TeX for the printed form. */
  tex?: string;
}

/** A wrong answer the key deducts marks for, recognised by its value. */
export interface NumberMistake {
  id: string;
  value: number;
  message: string;
}

/** A convention the key also accepts (e.g. v′ = 1 − v): checked as correct, with a note. */
export interface NumberAlternative {
  value: number;
  message: string;
  /** The convention's id (e.g. 'v-flip'): a variant's answers must use one convention throughout. */
  convention?: string;
}

/**
 * What a student typed for an earlier answer, as the follow-through rules read it: a number (null
 * for "none"), a compiled formula, or a chosen option.
 */
export type OwnValue = number | null | Fn | string;

/**
 * Follow-through: this answer recomputed from the student's own earlier answers `from`. `matches`
 * says whether the student's answer is what their own (wrong) earlier answers give.
 */
export interface FollowRule {
  from: readonly string[];
  matches: (own: Readonly<Record<string, OwnValue>>, answer: OwnValue) => boolean;
}

interface AnswerBase {
  name: string;
  label: string;
  /** The expected answer in the key's form, as TeX (the printed key); else the number or formula. */
  tex?: string;
  follow?: FollowRule[];
}

export interface NumberAnswer extends AnswerBase {
  kind: 'number';
  /** The expected value; null where the answer is "none" (no root, no hit). */
  expected: number | null;
  alternatives: NumberAlternative[];
  mistakes: NumberMistake[];
}

export interface FormulaMistake {
  id: string;
  fns: Fn[];
  message: string;
}

export interface FormulaAlternative {
  fn: Fn;
  message: string;
  convention?: string;
}

export interface FormulaAnswer extends AnswerBase {
  kind: 'formula';
  /** The variable names the student writes (one here: theta, phi or xi). */
  variables: readonly string[];
  /** Open interval of each variable where the two formulas are compared. */
  domain: readonly (readonly [number, number])[];
  expected: Fn;
  /** The expected formula in mathjs syntax (shown as the expected answer). */
  expectedText: string;
  alternatives: FormulaAlternative[];
  mistakes: FormulaMistake[];
}

export interface ChoiceMistake {
  id: string;
  value: string;
  message: string;
}

export interface ChoiceAnswer extends AnswerBase {
  kind: 'choice';
  options: readonly string[];
  expected: string;
  mistakes: ChoiceMistake[];
  /** Why the expected option is right (shown after checking). */
  why: string;
}

export type AnswerSpec = NumberAnswer | FormulaAnswer | ChoiceAnswer;

/** One line of the worked solution: a sentence, a display formula, or both. */
export interface SolutionStep {
  text?: string;
  tex?: string;
}

/** One sub-question: a prompt, the answers it asks for, its hint and its worked step. */
export interface Part {
  id: string;
  prompt: string;
  /** The prompt as printed on paper (no typing instructions), when it differs. */
  paperPrompt?: string;
  answers: AnswerSpec[];
  /** One hint: the first step of this part's derivation, in the variant's numbers. */
  hint: SolutionStep[];
  /** This part's worked solution (every step the key awards marks for), in the variant's numbers. */
  steps: SolutionStep[];
}

export interface Variant {
  question: QuestionId;
  seed: number;
  title: string;
  /** The question as the exam states it, with this variant's numbers (plain text). */
  statement: string;
  givens: Given[];
  parts: Part[];
  /** The worked solution in full: {@link Variant.intro} (when any), then each part's steps. */
  solution: SolutionStep[];
  /** Steps that come before every part (a table of the given data), if any. */
  intro: SolutionStep[];
  /** Hash route of the matching scene in this variant's configuration. */
  sceneHref: string;
  sceneLabel: string;
  /** Remarks (e.g. what the scene does differently). */
  notes: string[];
}

/** The full worked solution from its intro and the parts' steps. */
export function assembleSolution(intro: SolutionStep[], parts: Part[]): SolutionStep[] {
  return [...intro, ...parts.flatMap((p) => p.steps)];
}

/** Every answer of a variant, in order. */
export function allAnswers(v: Variant): AnswerSpec[] {
  return v.parts.flatMap((p) => p.answers);
}

// ---------------------------------------------------------------------------------------------
// Numbers in the worked solution (TeX) and vectors (src/core/format.ts formats the digits).

/** A number for TeX: 6 significant digits, × 10^{e} for exponents. */
export function tn(x: number, digits = 6): string {
  const s = formatSignificant(x, digits, 'e');
  const m = /^(-?[\d.]+)e(-?\d+)$/.exec(s);
  return m ? `${m[1]} \\times 10^{${m[2]}}` : s;
}

/** Like {@link tn}, in parentheses when negative (for substitution into a product). */
export function tp(x: number, digits = 6): string {
  return x < 0 ? `(${tn(x, digits)})` : tn(x, digits);
}

/** A vector as "x,y,z" with String(x) (the contract's vector format). */
export function vecValue(v: readonly number[]): string {
  return v.map((x) => String(x)).join(',');
}

/** A vector for people: "(x, y, z)" with up to `digits` significant digits. */
export function vecDisplay(v: readonly number[], digits = 6): string {
  return `(${v.map((x) => formatSignificant(x, digits, 'e')).join(', ')})`;
}

/** Round to `d` decimals (for givens chosen to be exactly the printed numbers). */
export function roundTo(x: number, d: number): number {
  const s = 10 ** d;
  return Math.round(x * s) / s + 0;
}

/** A small rational p/q for TeX and for mathjs text. */
export interface Rational {
  p: number;
  q: number;
}

export function ratValue(r: Rational): number {
  return r.p / r.q;
}

export function ratTex(r: Rational): string {
  if (r.q === 1) return String(r.p);
  return `${r.p < 0 ? '-' : ''}\\tfrac{${Math.abs(r.p)}}{${r.q}}`;
}

export function ratText(r: Rational): string {
  return r.q === 1 ? String(r.p) : `${r.p}/${r.q}`;
}
