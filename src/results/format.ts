/**
 * The results file a learner downloads from the practice pages ("Download my results") and the
 * class results page (#/results) collates. JSON:
 *
 *   { "format": "render-math-lab-results", "formatVersion": 1, "app": "0.1.0",
 *     "student": "Ada", "created": "2025-…Z",
 *     "attempts": [ { "question": "q3", "seed": 17, "time": "2025-…Z",
 *                     "answers": { "u-nearest": "0.5", … }, "verdicts": { "u-nearest": "correct", … },
 *                     "forfeited": [ "u-nearest" ] } ] }
 *
 * `forfeited` (optional) names the answers whose part's answer the page had shown before that check:
 * they earn nothing, as on the page.
 * The verdicts are what the page showed; the results page ignores them for scoring and recomputes
 * every verdict from the seed and the typed answers (it only reports where they disagree).
 */
import { isQuestionId, type QuestionId } from '../practice/model';

export const RESULTS_FORMAT = 'render-math-lab-results';

export interface Attempt {
  question: QuestionId;
  seed: number;
  time: string;
  answers: Record<string, string>;
  verdicts: Record<string, string>;
  /** Answers whose part's answer had been shown before this check: they earn nothing. */
  forfeited?: string[];
}

export interface ResultsFile {
  format: typeof RESULTS_FORMAT;
  formatVersion: 1;
  app: string;
  student: string;
  created: string;
  attempts: Attempt[];
}

export const MAX_ATTEMPTS = 500;
const MAX_TEXT = 500;

function strings(x: unknown, max: number): Record<string, string> {
  const out: Record<string, string> = {};
  if (!x || typeof x !== 'object' || Array.isArray(x)) return out;
  let n = 0;
  for (const [k, v] of Object.entries(x as Record<string, unknown>)) {
    if (typeof v !== 'string' || k.length > 60 || ++n > max) continue;
    out[k] = v.slice(0, MAX_TEXT);
  }
  return out;
}

/** The `forfeited` list of an attempt (answer names), when it has one. */
function names(x: unknown): { forfeited?: string[] } {
  if (!Array.isArray(x)) return {};
  const list = x.filter((n): n is string => typeof n === 'string' && n.length <= 60).slice(0, 40);
  return list.length ? { forfeited: list } : {};
}

/** Read a results file's text; a clear message when it is not one. Never throws. */
export function parseResultsFile(
  text: string,
): { ok: true; file: ResultsFile; skipped: number } | { ok: false; error: string } {
  let d: unknown;
  try {
    d = JSON.parse(text);
  } catch {
    return { ok: false, error: 'not JSON (is it a Render Math Lab results file?)' };
  }
  if (!d || typeof d !== 'object') return { ok: false, error: 'not a results file' };
  const o = d as Record<string, unknown>;
  if (o.format !== RESULTS_FORMAT)
    return {
      ok: false,
      error: `not a Render Math Lab results file (format ${JSON.stringify(String(o.format ?? '')).slice(0, 40)})`,
    };
  if (!Array.isArray(o.attempts)) return { ok: false, error: 'the file has no attempts list' };
  const attempts: Attempt[] = [];
  let skipped = 0;
  for (const a of o.attempts.slice(0, MAX_ATTEMPTS)) {
    const x = (a ?? {}) as Record<string, unknown>;
    const q = String(x.question ?? '');
    const seed = x.seed;
    if (
      !isQuestionId(q) ||
      typeof seed !== 'number' ||
      !Number.isInteger(seed) ||
      seed < 0 ||
      seed > 0xffffffff
    ) {
      skipped++;
      continue;
    }
    attempts.push({
      question: q,
      seed,
      time: typeof x.time === 'string' ? x.time.slice(0, 40) : '',
      answers: strings(x.answers, 40),
      verdicts: strings(x.verdicts, 40),
      ...names(x.forfeited),
    });
  }
  skipped += Math.max(0, o.attempts.length - MAX_ATTEMPTS);
  return {
    ok: true,
    skipped,
    file: {
      format: RESULTS_FORMAT,
      formatVersion: 1,
      app: typeof o.app === 'string' ? o.app.slice(0, 40) : '',
      student: typeof o.student === 'string' ? o.student.trim().slice(0, 80) : '',
      created: typeof o.created === 'string' ? o.created.slice(0, 40) : '',
      attempts,
    },
  };
}
