/**
 * The learner's own results log behind "Download my results": every check on the practice pages
 * (question, seed, typed answers, verdicts, time), kept in this browser (localStorage key
 * `rml:practice-results`, the last 500 checks). Registered as a practice extension when the
 * practice chunk loads. Storage can be missing or full: then the log lives for the page only.
 */
import { addPracticeExtension } from '../practice/extensions';
import { APP_VERSION } from '../lms/version';
import { MAX_ATTEMPTS, RESULTS_FORMAT, parseResultsFile, type Attempt, type ResultsFile } from './format';

export const RESULTS_KEY = 'rml:practice-results';
export const NAME_KEY = 'rml:practice-name';

let memory: Attempt[] | null = null;

export function loadAttempts(): Attempt[] {
  if (memory) return memory;
  try {
    const raw = window.localStorage.getItem(RESULTS_KEY);
    const p = raw ? parseResultsFile(raw) : null;
    memory = p && p.ok ? p.file.attempts : [];
  } catch {
    memory = [];
  }
  return memory;
}

function save(attempts: Attempt[]): void {
  memory = attempts;
  try {
    window.localStorage.setItem(RESULTS_KEY, JSON.stringify(resultsFile('')));
  } catch {
    /* storage unavailable: kept for this page only */
  }
}

export function resultsFile(student: string): ResultsFile {
  return {
    format: RESULTS_FORMAT,
    formatVersion: 1,
    app: APP_VERSION,
    student: student.trim().slice(0, 80),
    created: new Date().toISOString(),
    attempts: loadAttempts(),
  };
}

export function clearAttempts(): void {
  save([]);
}

export function loadName(): string {
  try {
    return window.localStorage.getItem(NAME_KEY) ?? '';
  } catch {
    return '';
  }
}

export function saveName(name: string): void {
  try {
    window.localStorage.setItem(NAME_KEY, name.slice(0, 80));
  } catch {
    /* not kept */
  }
}

let registered = false;

/** Start logging checks (once per page). */
export function startRecording(): void {
  if (registered) return;
  registered = true;
  addPracticeExtension({
    onCheck: (r) => {
      const answers: Record<string, string> = {};
      const verdicts: Record<string, string> = {};
      for (const a of r.answers) {
        if (a.verdict === 'blank') continue;
        answers[a.name] = a.response;
        verdicts[a.name] = a.verdict;
      }
      save(
        [...loadAttempts(), { question: r.question, seed: r.seed, time: r.time, answers, verdicts }].slice(
          -MAX_ATTEMPTS,
        ),
      );
    },
  });
}
