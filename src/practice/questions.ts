/**
 * The six practice questions: metadata and the variant generator of each (pure). The metadata
 * alone, without the generators and the core they use, is ./questionList.ts.
 */
import type { QuestionId, Variant } from './model';
import { QUESTION_LIST, type QuestionMeta } from './questionList';
import { q1Variant } from './q1';
import { q2Variant } from './q2';
import { q3Variant } from './q3';
import { q4Variant } from './q4';
import { q5Variant } from './q5';
import { q6Variant } from './q6';

export interface QuestionInfo extends QuestionMeta {
  generate: (seed: number) => Variant;
}

const GENERATORS: Record<QuestionId, (seed: number) => Variant> = {
  q1: q1Variant,
  q2: q2Variant,
  q3: q3Variant,
  q4: q4Variant,
  q5: q5Variant,
  q6: q6Variant,
};

/** The practice questions, in exam order, each with its generator. */
export const QUESTIONS: readonly QuestionInfo[] = QUESTION_LIST.map((q) => ({
  ...q,
  generate: GENERATORS[q.id],
}));

export function questionInfo(id: QuestionId): QuestionInfo {
  return QUESTIONS.find((q) => q.id === id)!;
}
