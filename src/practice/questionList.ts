/**
 * The practice questions as the index and the worksheet builder list them: id, number, title and
 * blurb, from the catalogue. Light on purpose (no variant generator, none of the core): the
 * practice index loads only this; a question page adds the generators (./questions.ts).
 */
import { QUESTIONS as CATALOGUE } from '../kit/catalogue';
import type { QuestionId } from './model';

export interface QuestionMeta {
  id: QuestionId;
  n: number;
  title: string;
  blurb: string;
}

/** The practice questions, in exam order: title and blurb from the catalogue. */
export const QUESTION_LIST: readonly QuestionMeta[] = CATALOGUE.map((q) => ({
  id: q.practice.id as QuestionId,
  n: q.n,
  title: q.title,
  blurb: q.practice.blurb,
}));

export function questionMeta(id: QuestionId): QuestionMeta {
  return QUESTION_LIST.find((q) => q.id === id)!;
}

/** Seed of the k-th variant of a question on a worksheet with base seed `seed` (wraps at 2³²). */
export function sheetSeed(seed: number, k: number): number {
  return (seed + k) >>> 0;
}
