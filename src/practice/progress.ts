/**
 * Practice progress, kept in this browser only (localStorage, key `rml:practice-progress`, per
 * learner inside an LMS package: ./learnerScope.ts): per
 * question, the variants (seeds) checked at least once and those answered fully correctly.
 * Storage can be missing, full or forbidden (private mode, sandboxed iframes): every access is
 * guarded and progress then simply is not kept.
 */
import { QUESTION_IDS, type QuestionId } from './model';
import { readPerQuestion } from './stored';
import { scopedKey } from './learnerScope';

export const PROGRESS_KEY = 'rml:practice-progress';
const MAX_SEEDS = 500;

export interface QuestionProgress {
  attempted: number[];
  correct: number[];
}

export type Progress = Record<QuestionId, QuestionProgress>;

function empty(): Progress {
  const p = Object.create(null) as Progress;
  for (const q of QUESTION_IDS) p[q] = { attempted: [], correct: [] };
  return p;
}

function seeds(x: unknown): number[] {
  return Array.isArray(x)
    ? x.filter((s): s is number => Number.isInteger(s) && s >= 0 && s <= 0xffffffff).slice(-MAX_SEEDS)
    : [];
}

/**
 * Stored progress as it can be true: each seed once, and a variant answered fully correctly was
 * also tried (a hand-edited or corrupted `{"attempted":[7],"correct":[7,7,7]}` reads 1 tried, 1 correct).
 */
function normalise(attempted: number[], correct: number[]): QuestionProgress {
  const c = [...new Set(correct)];
  const a = [...new Set([...attempted, ...c])].slice(-MAX_SEEDS);
  return { attempted: a, correct: c.filter((s) => a.includes(s)) };
}

export function loadProgress(): Progress {
  const p = empty();
  readPerQuestion(scopedKey(PROGRESS_KEY), (q, e) => {
    p[q] = normalise(seeds(e.attempted), seeds(e.correct));
  });
  return p;
}

function save(p: Progress): void {
  try {
    window.localStorage.setItem(scopedKey(PROGRESS_KEY), JSON.stringify(p));
  } catch {
    /* storage unavailable: progress is not kept */
  }
}

/** Record a check of variant `seed` of question `q`; `allCorrect` when every answer was correct. */
export function recordCheck(q: QuestionId, seed: number, allCorrect: boolean): Progress {
  const p = loadProgress();
  const e = p[q];
  if (!e.attempted.includes(seed)) e.attempted = [...e.attempted, seed].slice(-MAX_SEEDS);
  if (allCorrect && !e.correct.includes(seed)) e.correct = [...e.correct, seed].slice(-MAX_SEEDS);
  save(p);
  return p;
}

export function resetProgress(): Progress {
  try {
    window.localStorage.removeItem(scopedKey(PROGRESS_KEY));
  } catch {
    /* nothing to remove */
  }
  return empty();
}
