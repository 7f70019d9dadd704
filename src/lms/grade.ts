/**
 * Grading a learner's typed answers from the question and seed alone, for everything that reports
 * or collates results outside the practice page (SCORM, cmi5, the class results page). The verdicts
 * come from the practice checker itself, so a score recomputed here is the score the page showed,
 * and a results file whose verdicts were edited by hand cannot raise it.
 */
import { allAnswers, QUESTION_IDS, type AnswerSpec, type QuestionId, type Variant } from '../practice/model';
import { questionInfo } from '../practice/questions';
import { gradeAnswers } from '../practice/session';

export interface GradedAnswer {
  name: string;
  label: string;
  kind: AnswerSpec['kind'];
  response: string;
  /** correct | consistent | incorrect | invalid | mistake:<id> | blank */
  verdict: string;
  message: string;
}

export interface GradedAttempt {
  question: QuestionId;
  seed: number;
  answers: GradedAnswer[];
  /** Number of correct answers. */
  score: number;
  /** Number of answers the question asks for. */
  max: number;
}

const variants = new Map<string, Variant>();

/** The variant of (q, seed), memoised (generators are pure; a class's files repeat variants). */
export function variantOf(q: QuestionId, seed: number): Variant {
  const k = `${q}:${seed}`;
  let v = variants.get(k);
  if (!v) {
    v = questionInfo(q).generate(seed);
    if (variants.size > 2000) variants.clear();
    variants.set(k, v);
  }
  return v;
}

/** The named mistake of a verdict value (`mistake:no-sin-jacobian` → `no-sin-jacobian`), or null. */
export function mistakeOf(verdict: string): string | null {
  return verdict.startsWith('mistake:') ? verdict.slice('mistake:'.length) : null;
}

/**
 * Check every typed answer of (q, seed) as the practice page does; blank answers are 'blank'. The
 * score counts correct answers (a follow-through 'consistent' answer is not counted).
 */
export async function gradeAttempt(
  q: QuestionId,
  seed: number,
  responses: Readonly<Record<string, string>>,
): Promise<GradedAttempt> {
  const v = variantOf(q, seed);
  const texts: Record<string, string> = {};
  for (const a of allAnswers(v))
    texts[a.name] = typeof responses[a.name] === 'string' ? responses[a.name].slice(0, 500) : '';
  // the page's own grading: conventions across the variant, follow-through from earlier answers
  const verdicts = await gradeAnswers(v, texts);
  const out: GradedAnswer[] = allAnswers(v).map((a) => ({
    name: a.name,
    label: a.label,
    kind: a.kind,
    response: texts[a.name],
    verdict: verdicts[a.name]?.value ?? 'blank',
    message: verdicts[a.name]?.message ?? '',
  }));
  const score = out.filter((a) => a.verdict === 'correct').length;
  return { question: q, seed, answers: out, score, max: out.length };
}

/** Read a question list like "1,3,5" or "q1,q3" (null when any entry is not a question 1–6). */
export function parseQuestionList(text: string): QuestionId[] | null {
  const ids = text
    .split(',')
    .map((s) => s.trim())
    .filter(Boolean)
    .map((s) => `q${s.replace(/^q/i, '')}`);
  if (!ids.length || ids.some((s) => !(QUESTION_IDS as readonly string[]).includes(s))) return null;
  return [...new Set(ids as QuestionId[])].sort();
}
