/**
 * SCORM 1.2 and SCORM 2004 (4th edition) runtime of the practice package.
 *
 * Finds the LMS's API object (`API` for 1.2, `API_1484_11` for 2004) by the standard search: up the
 * chain of parent windows, then the opener and its parents. Initializes, reads the learner id
 * (cmi.core.student_id / cmi.learner_id) from which the variant seeds derive, and resumes from
 * suspend_data. Each Check records one interaction per answered field (id, type fill-in, the typed
 * response, the expected answer, the result (neutral for a follow-through answer); the named mistake in the description in 2004, and as
 * the interaction's objective id in 1.2, which has no description), the score and the status, and
 * commits. Leaving the page sets the session time and exit = suspend, and terminates.
 *
 * Scores: 2004 reports raw = correct answers, min 0, max = answers asked, scaled = raw / max;
 * 1.2 reports the same ratio as a percentage (raw 0–100, min 0, max 100), the range SCORM 1.2
 * LMSs read. Status: incomplete until every question of the package has been checked once, then
 * passed or failed against the mastery score (the LMS's cmi.student_data.mastery_score or
 * cmi.scaled_passing_score when it sets one, else the package's).
 */
import type { CheckRecord } from '../practice/extensions';
import { expectedText } from '../practice/check';
import { allAnswers, type QuestionId } from '../practice/model';
import { mistakeOf, variantOf } from './grade';
import type { LmsConfig } from './config';
import { PracticeState, type PriorResult } from './state';

interface Api12 {
  LMSInitialize(s: ''): string;
  LMSFinish(s: ''): string;
  LMSGetValue(k: string): string;
  LMSSetValue(k: string, v: string): string;
  LMSCommit(s: ''): string;
  LMSGetLastError(): string;
}
interface Api2004 {
  Initialize(s: ''): string;
  Terminate(s: ''): string;
  GetValue(k: string): string;
  SetValue(k: string, v: string): string;
  Commit(s: ''): string;
  GetLastError(): string;
}

/** The standard API search: parents (at most 500 levels), then the opener's chain. */
export function findApi<T>(start: Window, name: 'API' | 'API_1484_11'): T | null {
  const scan = (w: Window | null): T | null => {
    let win = w;
    for (let tries = 0; win && tries < 500; tries++) {
      try {
        const api = (win as unknown as Record<string, unknown>)[name];
        if (api && typeof api === 'object') return api as T;
      } catch {
        /* another origin's window: keep climbing */
      }
      if (!win.parent || win.parent === win) break;
      win = win.parent;
    }
    return null;
  };
  let api = scan(start);
  if (!api) {
    try {
      api = scan(start.opener as Window | null);
    } catch {
      api = null;
    }
  }
  return api;
}

/** The calls both versions share, under one set of names. */
interface Driver {
  version: '1.2' | '2004';
  init(): boolean;
  get(k: string): string;
  set(k: string, v: string): boolean;
  commit(): boolean;
  finish(): boolean;
  lastError(): string;
}

/** Each version's names for the shared calls (the versions differ only in the names). */
const CALLS = {
  '1.2': {
    init: 'LMSInitialize',
    get: 'LMSGetValue',
    set: 'LMSSetValue',
    commit: 'LMSCommit',
    finish: 'LMSFinish',
    lastError: 'LMSGetLastError',
  },
  '2004': {
    init: 'Initialize',
    get: 'GetValue',
    set: 'SetValue',
    commit: 'Commit',
    finish: 'Terminate',
    lastError: 'GetLastError',
  },
} as const satisfies Record<'1.2', Record<string, keyof Api12>> &
  Record<'2004', Record<string, keyof Api2004>>;

function driver(version: Driver['version'], api: Api12 | Api2004): Driver {
  const names = CALLS[version];
  const call = (name: string, ...args: string[]): string => {
    const fn = (api as unknown as Record<string, (...a: string[]) => unknown>)[name];
    return String(fn?.apply(api, args) ?? '');
  };
  return {
    version,
    init: () => call(names.init, '') === 'true',
    get: (k) => call(names.get, k),
    set: (k, v) => call(names.set, k, v) === 'true',
    commit: () => call(names.commit, '') === 'true',
    finish: () => call(names.finish, '') === 'true',
    lastError: () => call(names.lastError),
  };
}

const pad = (n: number, w = 2) => String(Math.floor(n)).padStart(w, '0');
/** SCORM 1.2 CMITimespan HHHH:MM:SS.SS. */
export function time12(ms: number): string {
  const s = Math.max(0, ms) / 1000;
  return `${pad(s / 3600, 4)}:${pad((s / 60) % 60)}:${pad(s % 60)}.${pad((s * 100) % 100)}`;
}
/** SCORM 2004 duration PT#H#M#S. */
export function time2004(ms: number): string {
  const s = Math.max(0, ms) / 1000;
  return `PT${Math.floor(s / 3600)}H${Math.floor((s / 60) % 60)}M${(s % 60).toFixed(2)}S`;
}

/** A fill-in text SCORM accepts: no [,] or [.] delimiters, no leading {, clipped. */
function fillIn(s: string, n: number): string {
  return s
    .replace(/\[[,.]\]/g, ' ')
    .replace(/^\{/, '(')
    .slice(0, n);
}

export interface ScormSession {
  version: '1.2' | '2004';
  learnerId: string;
  learnerName: string;
  state: PracticeState;
  /** Report a check; false when the LMS refused a value or the commit (the result may be lost). */
  onCheck(r: CheckRecord): boolean;
  onInput(): void;
  finish(): void;
  /** The last SCORM error code the LMS reported ('0' when none). */
  errors: string[];
}

/** Connect to the LMS, or null when no API is found or it refuses to initialize. */
export function connectScorm(config: LmsConfig, win: Window = window): ScormSession | null {
  const v12 = config.kind === 'scorm12';
  const api = v12 ? findApi<Api12>(win, 'API') : findApi<Api2004>(win, 'API_1484_11');
  if (!api) return null;
  const d = driver(v12 ? '1.2' : '2004', api);
  let ok = false;
  try {
    ok = d.init();
  } catch {
    ok = false;
  }
  if (!ok) return null;
  const started = Date.now();
  const errors: string[] = [];
  const set = (k: string, v: string) => {
    if (!d.set(k, v)) errors.push(`${k}: ${d.lastError()}`);
  };
  const K = v12
    ? {
        learner: 'cmi.core.student_id',
        name: 'cmi.core.student_name',
        suspend: 'cmi.suspend_data',
        mastery: 'cmi.student_data.mastery_score',
        limit: 4096,
      }
    : {
        learner: 'cmi.learner_id',
        name: 'cmi.learner_name',
        suspend: 'cmi.suspend_data',
        mastery: 'cmi.scaled_passing_score',
        limit: 64000,
      };
  const learnerId = d.get(K.learner) || 'anonymous';
  const learnerName = d.get(K.name);
  const m = Number.parseFloat(d.get(K.mastery));
  const mastery = Number.isFinite(m) && m > 0 ? (v12 ? m / 100 : m) : config.mastery;
  const state = new PracticeState(config.questions, learnerId, config.seed, Math.min(1, mastery));
  state.prior = priorResult(d, v12);
  const saved = d.get(K.suspend);
  if (saved) state.restore(saved);
  if (v12) {
    const st = d.get('cmi.core.lesson_status');
    if (st === 'not attempted' || st === '') set('cmi.core.lesson_status', 'incomplete');
  } else {
    const st = d.get('cmi.completion_status');
    if (st === 'unknown' || st === 'not attempted' || st === '') set('cmi.completion_status', 'incomplete');
  }

  const writeSuspend = () => set(K.suspend, state.serialise(K.limit));
  const writeScore = () => {
    const t = state.totals();
    if (v12) {
      set('cmi.core.score.min', '0');
      set('cmi.core.score.max', '100');
      set('cmi.core.score.raw', String(Math.round(t.scaled * 10000) / 100));
      set('cmi.core.lesson_status', t.complete ? (t.passed ? 'passed' : 'failed') : 'incomplete');
    } else {
      set('cmi.score.min', '0');
      set('cmi.score.max', String(t.max));
      set('cmi.score.raw', String(t.raw));
      set('cmi.score.scaled', String(Math.round(t.scaled * 1e6) / 1e6));
      set('cmi.progress_measure', String(Math.round((t.checked / t.questions) * 1e6) / 1e6));
      set('cmi.completion_status', t.complete ? 'completed' : 'incomplete');
      set('cmi.success_status', t.complete ? (t.passed ? 'passed' : 'failed') : 'unknown');
    }
  };

  let finished = false;
  // typed answers reach the LMS's suspend data at once, and are committed after a pause in typing
  // (not only at a Check), so a relaunch after a crash finds them
  let commitTimer: ReturnType<typeof setTimeout> | null = null;
  return {
    version: d.version,
    learnerId,
    learnerName,
    state,
    errors,
    onInput: () => {
      if (finished) return;
      writeSuspend();
      if (commitTimer) clearTimeout(commitTimer);
      commitTimer = setTimeout(() => {
        commitTimer = null;
        if (!finished && !d.commit()) errors.push(`commit: ${d.lastError()}`);
      }, 2000);
    },
    onCheck: (r) => {
      if (finished) return false;
      const before = errors.length;
      const info = state.byQuestion.get(r.question);
      const now = new Date();
      for (const a of r.answers) {
        if (a.verdict === 'blank') continue;
        const n = Number.parseInt(d.get('cmi.interactions._count'), 10) || 0;
        const p = `cmi.interactions.${n}.`;
        const mistake = mistakeOf(a.verdict);
        const expected = info ? expectedOf(r.question, r.seed, a.name) : '';
        if (v12) {
          set(`${p}id`, `${r.question}-${r.seed}-${a.name}`.replace(/[^\x21-\x7e]/g, '_').slice(0, 255));
          set(`${p}type`, 'fill-in');
          if (mistake) set(`${p}objectives.0.id`, `mistake-${mistake}`.slice(0, 255));
          set(`${p}time`, `${pad(now.getHours())}:${pad(now.getMinutes())}:${pad(now.getSeconds())}`);
          if (expected) set(`${p}correct_responses.0.pattern`, fillIn(expected, 255));
          set(`${p}student_response`, fillIn(a.response, 255));
          set(`${p}result`, interactionResult(a.verdict, 'wrong'));
        } else {
          set(`${p}id`, `urn:render-math-lab:${r.question}:${r.seed}:${a.name}`);
          set(`${p}type`, 'fill-in');
          // SCORM 2004's time type allows a zone designator only after the fraction of a second
          set(`${p}timestamp`, `${now.toISOString().slice(0, 22)}Z`);
          if (expected) set(`${p}correct_responses.0.pattern`, fillIn(expected, 250));
          set(`${p}learner_response`, fillIn(a.response, 250));
          set(`${p}result`, interactionResult(a.verdict, 'incorrect'));
          set(
            `${p}description`,
            fillIn(mistake ? `${a.name}: mistake ${mistake}: ${a.message}` : `${a.name}: ${a.verdict}`, 250),
          );
        }
      }
      writeScore();
      writeSuspend();
      if (!d.commit()) errors.push(`commit: ${d.lastError()}`);
      return errors.length === before;
    },
    finish: () => {
      if (finished) return;
      finished = true;
      if (commitTimer) clearTimeout(commitTimer);
      writeSuspend();
      if (v12) {
        set('cmi.core.session_time', time12(Date.now() - started));
        set('cmi.core.exit', 'suspend');
      } else {
        set('cmi.session_time', time2004(Date.now() - started));
        set('cmi.exit', 'suspend');
      }
      d.commit();
      d.finish();
    },
  };
}

/**
 * The result the LMS holds from earlier sessions (SCORM 1.2: the 0–100 raw score and the lesson
 * status; 2004: the scaled score, completion and success), so that a relaunch whose saved state
 * is lost or unreadable never reports less.
 */
function priorResult(d: Driver, v12: boolean): PriorResult {
  const num = (k: string) => {
    const t = d.get(k);
    const x = t.trim() === '' ? Number.NaN : Number(t);
    return Number.isFinite(x) ? x : null;
  };
  if (v12) {
    const raw = num('cmi.core.score.raw');
    const max = num('cmi.core.score.max') ?? 100;
    const st = d.get('cmi.core.lesson_status');
    return {
      scaled: raw !== null && max > 0 ? Math.min(1, Math.max(0, raw / max)) : null,
      complete: st === 'passed' || st === 'failed' || st === 'completed',
      passed: st === 'passed',
    };
  }
  const scaled = num('cmi.score.scaled');
  return {
    scaled: scaled !== null ? Math.min(1, Math.max(0, scaled)) : null,
    complete: d.get('cmi.completion_status') === 'completed',
    passed: d.get('cmi.success_status') === 'passed',
  };
}

function expectedOf(q: QuestionId, seed: number, name: string): string {
  const a = allAnswers(variantOf(q, seed)).find((x) => x.name === name);
  return a ? expectedText(a) : '';
}

/**
 * A checked answer's interaction result: correct, unanticipated (not a valid answer), neutral (a
 * follow-through answer: consistent with the learner's own earlier, wrong answer) or wrong, which
 * SCORM 1.2 spells 'wrong' and SCORM 2004 'incorrect'.
 */
function interactionResult(verdict: string, wrong: 'wrong' | 'incorrect'): string {
  if (verdict === 'correct') return 'correct';
  if (verdict === 'invalid') return 'unanticipated';
  if (verdict === 'consistent') return 'neutral';
  return wrong;
}
