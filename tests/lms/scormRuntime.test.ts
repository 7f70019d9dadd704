/**
 * The SCORM runtime (src/lms/scorm.ts) against scorm-again playing the LMS, in Node: the LMS gets
 * the marks the page states (best kept, nothing for a shown answer), never lower than it already
 * holds (a worse check, an unreadable saved state), refusals are reported, and a relaunch from the
 * LMS's committed data finds the typed answers.
 */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { Scorm12API, Scorm2004API } from 'scorm-again';
import { connectScorm, type ScormSession } from '../../src/lms/scorm';
import type { LmsConfig } from '../../src/lms/config';
import type { CheckRecord } from '../../src/practice/extensions';
import { checkRecord } from './checkRecord';
import { variantOf } from '../../src/lms/grade';
import { allAnswers, QUESTION_IDS, type QuestionId } from '../../src/practice/model';

type Api = InstanceType<typeof Scorm12API> | InstanceType<typeof Scorm2004API>;
type Version = '1.2' | '2004';
type Json = Record<string, any>;

const LEARNER = 'learner-7';

/** An LMS (scorm-again) for `version`, holding `json` from earlier sessions, and what it committed. */
function lms(version: Version, json?: Json) {
  const api: Api =
    version === '1.2'
      ? new Scorm12API({ autocommit: false, logLevel: 5 } as never)
      : new Scorm2004API({ autocommit: false, logLevel: 5 } as never);
  if (json) api.loadFromJSON(json, '');
  const cmi = api.cmi as unknown as Json;
  if (version === '1.2') {
    cmi.core.student_id = LEARNER;
    if (!json) cmi.student_data.mastery_score = '80';
  } else {
    cmi.learner_id = LEARNER;
    if (!json) cmi.scaled_passing_score = '0.8';
  }
  // what a crash leaves: the data as of the last commit
  const box = { committed: null as Json | null };
  api.on(version === '1.2' ? 'LMSCommit' : 'Commit', () => {
    box.committed = JSON.parse(JSON.stringify(api.cmi)) as Json;
  });
  return { api, box, cmi: () => JSON.parse(JSON.stringify(api.cmi)) as Json };
}

function connect(version: Version, api: Api, questions: QuestionId[]): ScormSession {
  const config: LmsConfig = {
    kind: version === '1.2' ? 'scorm12' : 'scorm2004',
    questions,
    seed: 11,
    mastery: 0.8,
    version: 'test',
  };
  const win = { [version === '1.2' ? 'API' : 'API_1484_11']: api, parent: null, opener: null };
  const s = connectScorm(config, win as unknown as Window);
  expect(s).not.toBeNull();
  return s!;
}

/** A check as the page reports it: `right` answers typed right, the others wrong, and its marks. */
function checkOf(s: ScormSession, q: QuestionId, right: number, marks?: number, shown = false): CheckRecord {
  return checkRecord(q, s.state.byQuestion.get(q)!.seed, right, marks, shown);
}

/** A Check on the page: the practice extension records it, then the runtime reports it (as launch.ts). */
function check(s: ScormSession, r: CheckRecord): boolean {
  let ok = false;
  s.state.extension({ onCheck: (x) => (ok = s.onCheck(x)), onInput: s.onInput }).onCheck!(r);
  return ok;
}

/** The score and status the LMS holds, as a 0–1 fraction and one word. */
function held(version: Version, cmi: Json): { scaled: number; status: string } {
  return version === '1.2'
    ? { scaled: Number(cmi.core.score.raw) / 100, status: cmi.core.lesson_status }
    : { scaled: Number(cmi.score.scaled), status: `${cmi.completion_status}/${cmi.success_status}` };
}
const PASSED = { '1.2': 'passed', '2004': 'completed/passed' };

beforeEach(() => vi.useFakeTimers());
afterEach(() => vi.useRealTimers());

describe.each(['1.2', '2004'] as const)('SCORM %s under scorm-again', (version) => {
  it('a worse later check never lowers the score the LMS holds (one question, then six)', () => {
    for (const questions of [['q5'], [...QUESTION_IDS]] as QuestionId[][]) {
      const { api, cmi } = lms(version);
      const s = connect(version, api, questions);
      for (const q of questions) {
        const n = s.state.byQuestion.get(q)!.max;
        expect(check(s, checkOf(s, q, n, n))).toBe(true);
      }
      expect(held(version, cmi())).toEqual({ scaled: 1, status: PASSED[version] });
      // worse checks: the page keeps the best (its marks), or states no marks (regraded from verdicts)
      const q = questions[questions.length - 1];
      const n = s.state.byQuestion.get(q)!.max;
      expect(check(s, checkOf(s, q, 1, n))).toBe(true);
      expect(check(s, checkOf(s, q, 0))).toBe(true);
      expect(held(version, cmi())).toEqual({ scaled: 1, status: PASSED[version] });
    }
  });

  it('answers shown before the check earn nothing at the LMS either', () => {
    const { api, cmi } = lms(version);
    const s = connect(version, api, ['q3']);
    const n = s.state.byQuestion.get('q3')!.max;
    // every answer typed right after "Show all answers": the page states 0 marks
    expect(check(s, checkOf(s, 'q3', n, 0, true))).toBe(true);
    const h = held(version, cmi());
    expect(h.scaled).toBe(0);
    expect(h.status).not.toMatch(/passed/);
    // the same without the page's marks: the forfeited answers still earn nothing
    const { api: api2, cmi: cmi2 } = lms(version);
    const s2 = connect(version, api2, ['q3']);
    check(s2, { ...checkOf(s2, 'q3', n, undefined, true) });
    expect(held(version, cmi2()).scaled).toBe(0);
  });

  it('an unreadable saved state never rewrites a passed 100', () => {
    const { api, cmi } = lms(version);
    const s = connect(version, api, ['q3', 'q5']);
    for (const q of ['q3', 'q5'] as const) {
      const n = s.state.byQuestion.get(q)!.max;
      check(s, checkOf(s, q, n, n));
    }
    s.finish();
    const kept = cmi();
    const good = String(kept.suspend_data);
    const other = JSON.parse(good) as { q: Record<string, { s: number }> };
    other.q.q3.s += 1;
    for (const saved of [
      '{',
      good.slice(0, Math.floor(good.length / 2)),
      'garbage',
      good.replace('"v":1', '"v":2'),
      JSON.stringify(other),
      '',
    ]) {
      const relaunch = lms(version, { ...kept, suspend_data: saved });
      const s2 = connect(version, relaunch.api, ['q3', 'q5']);
      // one question checked worse in the new session
      expect(check(s2, checkOf(s2, 'q3', 0, 0))).toBe(true);
      expect(held(version, relaunch.cmi())).toEqual({ scaled: 1, status: PASSED[version] });
    }
  });

  it('a refused value or commit is reported, not taken for recorded', () => {
    for (const refuse of ['set', 'commit'] as const) {
      const { api } = lms(version);
      const s = connect(version, api, ['q5']);
      const n = s.state.byQuestion.get('q5')!.max;
      const raw = version === '1.2' ? 'cmi.core.score.raw' : 'cmi.score.raw';
      const a = api as unknown as Record<string, (...x: string[]) => string>;
      if (refuse === 'set') {
        const name = version === '1.2' ? 'LMSSetValue' : 'SetValue';
        const real = a[name].bind(api);
        a[name] = (k: string, v: string) => (k === raw ? 'false' : real(k, v));
      } else a[version === '1.2' ? 'LMSCommit' : 'Commit'] = () => 'false';
      expect(check(s, checkOf(s, 'q5', n, n))).toBe(false);
      expect(s.errors.join(' ')).toMatch(refuse === 'set' ? /score\.raw/ : /commit/);
    }
  });

  it('a relaunch after a crash finds every typed answer the LMS committed', () => {
    const first = lms(version);
    const s = connect(version, first.api, ['q5']);
    const seed = s.state.byQuestion.get('q5')!.seed;
    const names = allAnswers(variantOf('q5', seed)).map((a) => a.name);
    const ext = s.state.extension({ onCheck: () => undefined, onInput: s.onInput });
    // typed one answer after another, each followed by a pause; then the page crashes (no finish)
    const typed: Record<string, string> = {};
    names.forEach((name, i) => {
      typed[name] = `${i + 1}.5`;
      ext.onInput!('q5', seed, { ...typed });
      vi.advanceTimersByTime(2500);
    });
    expect(first.box.committed).not.toBeNull();
    const relaunch = lms(version, first.box.committed!);
    const s2 = connect(version, relaunch.api, ['q5']);
    const back = s2.state.extension({ onCheck: () => undefined, onInput: () => undefined }).restore!(
      'q5',
      seed,
    );
    expect(back).toEqual(typed);
  });
});
