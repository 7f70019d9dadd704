/**
 * Each question's variant generator as a chunk of its own: a question page downloads its own
 * question's generator and the part of the core it uses, not the other five's (on a phone each
 * file is a round trip before the first paint). The worksheet, the LMS packages and the results
 * page, which need several questions, import them all through ./questions.ts.
 */
import type { QuestionId, Variant } from './model';

export type Generate = (seed: number) => Variant;

export const LOAD_GENERATOR: Record<QuestionId, () => Promise<Generate>> = {
  q1: () => import('./q1').then((m) => m.q1Variant),
  q2: () => import('./q2').then((m) => m.q2Variant),
  q3: () => import('./q3').then((m) => m.q3Variant),
  q4: () => import('./q4').then((m) => m.q4Variant),
  q5: () => import('./q5').then((m) => m.q5Variant),
  q6: () => import('./q6').then((m) => m.q6Variant),
};
