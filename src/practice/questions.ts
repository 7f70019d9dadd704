/** The six practice questions: metadata and the variant generator of each (pure). */
import { QUESTIONS as CATALOGUE } from '../kit/catalogue';
import { QUESTION_IDS, type QuestionId, type Variant } from './model';
import { q1Variant } from './q1';
import { q2Variant } from './q2';
import { q3Variant } from './q3';
import { q4Variant } from './q4';
import { q5Variant } from './q5';
import { q6Variant } from './q6';

export interface QuestionInfo {
  id: QuestionId;
  n: number;
  title: string;
  blurb: string;
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

/** The practice questions, in exam order: title and blurb from the catalogue, and a generator. */
export const QUESTIONS: readonly QuestionInfo[] = CATALOGUE.map((q) => ({
  id: q.practice.id as QuestionId,
  n: q.n,
  title: q.title,
  blurb: q.practice.blurb,
  generate: GENERATORS[q.practice.id as QuestionId],
}));

export function isQuestionId(s: string): s is QuestionId {
  return (QUESTION_IDS as readonly string[]).includes(s);
}

export function questionInfo(id: QuestionId): QuestionInfo {
  return QUESTIONS.find((q) => q.id === id)!;
}

/** Seed of the k-th variant of a question on a worksheet with base seed `seed` (wraps at 2³²). */
export function sheetSeed(seed: number, k: number): number {
  return (seed + k) >>> 0;
}
