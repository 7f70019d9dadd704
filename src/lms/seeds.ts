/**
 * Variant seeds of a learner in an LMS: a hash of (package seed, learner id, question), so each
 * learner gets their own numbers, the same in every session, and two learners rarely share them.
 * 32-bit FNV-1a over the UTF-16 code units, reduced to the practice pages' short seeds (0 … 99999).
 */
import type { QuestionId } from '../practice/model';

export function fnv1a(text: string): number {
  let h = 0x811c9dc5;
  for (let i = 0; i < text.length; i++) {
    h ^= text.charCodeAt(i);
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h >>> 0;
}

export function learnerSeed(learnerId: string, q: QuestionId, packageSeed = 0): number {
  return fnv1a(`${packageSeed >>> 0}|${learnerId}|${q}`) % 100000;
}
