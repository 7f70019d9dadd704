/**
 * The learner's own results log behind "Download my results": every check on the practice pages
 * (question, seed, typed answers, verdicts, the answers forfeited by Show answer, time), kept in this
 * browser (localStorage key `rml:practice-results`, per learner inside an LMS package:
 * ../practice/learnerScope.ts; the last 500 checks). Registered as a practice extension when the
 * practice chunk loads. Storage can be missing or full: then the log lives for the page only.
 *
 * Several tabs may log at once: each write reads what is stored and keeps the union of both logs
 * (by attempt), so no tab saves its stale copy over another's checks.
 */
import { addPracticeExtension } from '../practice/extensions';
import { scopedKey } from '../practice/learnerScope';
import { APP_VERSION } from '../lms/version';
import { MAX_ATTEMPTS, RESULTS_FORMAT, parseResultsFile, type Attempt, type ResultsFile } from './format';

export const RESULTS_KEY = 'rml:practice-results';
export const NAME_KEY = 'rml:practice-name';
/** Fired on window when the log or the name changed (here, in another tab, or by a reset). */
export const RECORD_CHANGED = 'rml:results-changed';

/** This page's checks that could not be stored (storage missing or full). */
let pending: Attempt[] = [];

function attemptId(a: Attempt): string {
  return JSON.stringify([a.question, a.seed, a.time, a.answers]);
}

function stored(): Attempt[] | null {
  try {
    const raw = window.localStorage.getItem(scopedKey(RESULTS_KEY));
    if (!raw) return [];
    const p = parseResultsFile(raw);
    return p.ok ? p.file.attempts : [];
  } catch {
    return null; // storage unavailable
  }
}

/** The union of logs, each attempt once, in time order, the last {@link MAX_ATTEMPTS}. */
export function mergeAttempts(...logs: readonly (readonly Attempt[])[]): Attempt[] {
  const byId = new Map<string, Attempt>();
  for (const log of logs) for (const a of log) if (!byId.has(attemptId(a))) byId.set(attemptId(a), a);
  return [...byId.values()]
    .sort((x, y) => (x.time < y.time ? -1 : x.time > y.time ? 1 : 0))
    .slice(-MAX_ATTEMPTS);
}

/** The log: what is stored (by any tab) and this page's checks that could not be. */
export function loadAttempts(): Attempt[] {
  return mergeAttempts(stored() ?? [], pending);
}

/** Add one attempt: read, merge, write (never an overwrite of another tab's checks). */
export function appendAttempt(a: Attempt): void {
  const attempts = mergeAttempts(stored() ?? [], pending, [a]);
  try {
    window.localStorage.setItem(scopedKey(RESULTS_KEY), JSON.stringify(fileOf('', attempts)));
    pending = [];
  } catch {
    pending = mergeAttempts(pending, [a]); // kept for this page only
  }
}

function fileOf(student: string, attempts: Attempt[]): ResultsFile {
  return {
    format: RESULTS_FORMAT,
    formatVersion: 1,
    app: APP_VERSION,
    student: student.trim().slice(0, 80),
    created: new Date().toISOString(),
    attempts,
  };
}

export function resultsFile(student: string): ResultsFile {
  return fileOf(student, loadAttempts());
}

function changed(): void {
  window.dispatchEvent(new Event(RECORD_CHANGED));
}

/** Forget the log and the name (Reset progress). */
export function clearAttempts(): void {
  pending = [];
  try {
    window.localStorage.removeItem(scopedKey(RESULTS_KEY));
    window.localStorage.removeItem(scopedKey(NAME_KEY));
  } catch {
    /* nothing to remove */
  }
  changed();
}

export function loadName(): string {
  try {
    return window.localStorage.getItem(scopedKey(NAME_KEY)) ?? '';
  } catch {
    return '';
  }
}

export function saveName(name: string): void {
  try {
    window.localStorage.setItem(scopedKey(NAME_KEY), name.slice(0, 80));
  } catch {
    /* not kept */
  }
}

/** The attempt a check record is logged as. */
export function attemptOf(r: {
  question: Attempt['question'];
  seed: number;
  time: string;
  answers: readonly { name: string; response: string; verdict: string }[];
  forfeited?: readonly string[];
}): Attempt {
  const answers: Record<string, string> = {};
  const verdicts: Record<string, string> = {};
  for (const a of r.answers) {
    if (a.verdict === 'blank') continue;
    answers[a.name] = a.response;
    verdicts[a.name] = a.verdict;
  }
  const forfeited = (r.forfeited ?? []).filter((n) => n in answers);
  return {
    question: r.question,
    seed: r.seed,
    time: r.time,
    answers,
    verdicts,
    ...(forfeited.length ? { forfeited } : {}),
  };
}

let registered = false;

/** Start logging checks (once per page). */
export function startRecording(): void {
  if (registered) return;
  registered = true;
  addPracticeExtension({
    onCheck: (r) => {
      appendAttempt(attemptOf(r));
      changed();
    },
    onReset: clearAttempts,
  });
  window.addEventListener('storage', (e) => {
    if (e.key === null || e.key === scopedKey(RESULTS_KEY) || e.key === scopedKey(NAME_KEY)) changed();
  });
}
