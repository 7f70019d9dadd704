/**
 * Reading a per-question record back from localStorage. Storage can be missing, full or forbidden,
 * and what it holds can be hand-edited or corrupted: anything that is not an object keyed by
 * question id yields nothing, and each question's entry is handed over only when it is an object.
 */
import { QUESTION_IDS, type QuestionId } from './model';

/** Call `take(q, entry)` for each question whose stored entry under `key` is an object. */
export function readPerQuestion(
  key: string,
  take: (q: QuestionId, entry: Record<string, unknown>) => void,
): void {
  try {
    const raw = window.localStorage.getItem(key);
    if (!raw) return;
    const data = JSON.parse(raw) as unknown;
    if (!data || typeof data !== 'object') return;
    for (const q of QUESTION_IDS) {
      if (!Object.hasOwn(data, q)) continue;
      const e = (data as Record<string, unknown>)[q];
      if (e && typeof e === 'object') take(q, e as Record<string, unknown>);
    }
  } catch {
    /* unreadable: start afresh */
  }
}
