/**
 * The best mark of each practice variant, kept in this browser only (localStorage, key
 * `rml:practice-scores`, per learner inside an LMS package: ./learnerScope.ts): per question, seed → best share of the marks (0 … 1). Storage can be
 * missing, full or forbidden: every access is guarded, and anything unreadable is ignored.
 */
import { QUESTION_IDS, type QuestionId } from './model';
import { readPerQuestion } from './stored';
import { scopedKey } from './learnerScope';

export const SCORES_KEY = 'rml:practice-scores';
const MAX_VARIANTS = 200;

export type Scores = Record<QuestionId, Record<string, number>>;

function empty(): Scores {
  const s = Object.create(null) as Scores;
  for (const q of QUESTION_IDS) s[q] = Object.create(null) as Record<string, number>;
  return s;
}

export function loadScores(): Scores {
  const out = empty();
  readPerQuestion(scopedKey(SCORES_KEY), (q, e) => {
    for (const [seed, v] of Object.entries(e)) {
      if (!/^\d{1,10}$/.test(seed) || Number(seed) > 0xffffffff) continue;
      if (typeof v === 'number' && v >= 0 && v <= 1) out[q][seed] = v;
    }
  });
  return out;
}

/** Keep `score` for variant `seed` of `q` if it beats the best so far; returns the best. */
export function recordScore(q: QuestionId, seed: number, score: number): number {
  const s = loadScores();
  const key = String(seed);
  const best = Math.max(s[q][key] ?? 0, Math.min(1, Math.max(0, score)));
  s[q][key] = best;
  // bounded: past MAX_VARIANTS per question, the lowest-scoring other variants are dropped
  const others = Object.keys(s[q]).filter((k) => k !== key);
  others.sort((x, y) => s[q][x] - s[q][y]);
  for (const k of others.slice(0, Math.max(0, others.length + 1 - MAX_VARIANTS))) delete s[q][k];
  try {
    window.localStorage.setItem(scopedKey(SCORES_KEY), JSON.stringify(s));
  } catch {
    /* storage unavailable: the score is not kept */
  }
  return best;
}

export function resetScores(): void {
  try {
    window.localStorage.removeItem(scopedKey(SCORES_KEY));
  } catch {
    /* nothing to remove */
  }
}
