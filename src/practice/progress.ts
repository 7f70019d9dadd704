/**
 * Practice progress, kept in this browser only (localStorage, key `rml:practice-progress`): per
 * question, the variants (seeds) checked at least once and those answered fully correctly.
 * Storage can be missing, full or forbidden (private mode, sandboxed iframes): every access is
 * guarded and progress then simply is not kept.
 */
import { QUESTION_IDS, type QuestionId } from './model';

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

export function loadProgress(): Progress {
  const p = empty();
  try {
    const raw = window.localStorage.getItem(PROGRESS_KEY);
    if (!raw) return p;
    const data = JSON.parse(raw) as unknown;
    if (!data || typeof data !== 'object') return p;
    for (const q of QUESTION_IDS) {
      if (!Object.hasOwn(data, q)) continue;
      const e = (data as Record<string, unknown>)[q] as { attempted?: unknown; correct?: unknown } | null;
      if (e && typeof e === 'object') p[q] = { attempted: seeds(e.attempted), correct: seeds(e.correct) };
    }
  } catch {
    /* unreadable: start afresh */
  }
  return p;
}

function save(p: Progress): void {
  try {
    window.localStorage.setItem(PROGRESS_KEY, JSON.stringify(p));
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
    window.localStorage.removeItem(PROGRESS_KEY);
  } catch {
    /* nothing to remove */
  }
  return empty();
}
