/**
 * What the LMS receives is what the page states: the page's marks (a shown answer earns nothing),
 * the best kept, never lowered by a relaunch whose saved state cannot be read, and a refused
 * SetValue or Commit is reported as a failure. A small in-memory LMS plays the SCORM API.
 */
import { describe, expect, it } from 'vitest';
import { connectScorm, type ScormSession } from '../../src/lms/scorm';
import { PracticeState } from '../../src/lms/state';
import type { CheckRecord } from '../../src/practice/extensions';
import type { LmsConfig } from '../../src/lms/config';

function fakeLms(version: '1.2' | '2004', data: Record<string, string> = {}, refuse = false) {
  const d: Record<string, string> = { ...data };
  const ok = (x: boolean) => (x ? 'true' : 'false');
  const api =
    version === '1.2'
      ? {
          LMSInitialize: () => 'true',
          LMSFinish: () => 'true',
          LMSGetValue: (k: string) => d[k] ?? '',
          LMSSetValue: (k: string, v: string) => (refuse ? 'false' : ((d[k] = v), 'true')),
          LMSCommit: () => ok(!refuse),
          LMSGetLastError: () => (refuse ? '101' : '0'),
        }
      : {
          Initialize: () => 'true',
          Terminate: () => 'true',
          GetValue: (k: string) => d[k] ?? '',
          SetValue: (k: string, v: string) => (refuse ? 'false' : ((d[k] = v), 'true')),
          Commit: () => ok(!refuse),
          GetLastError: () => (refuse ? '101' : '0'),
        };
  const win = { [version === '1.2' ? 'API' : 'API_1484_11']: api } as unknown as Window;
  (win as unknown as { parent: Window }).parent = win;
  return { win, d };
}

const config = (kind: LmsConfig['kind']): LmsConfig => ({
  kind,
  questions: ['q3'],
  seed: 1,
  mastery: 0.8,
  version: 't',
});

function record(s: PracticeState, earned: number, correct: boolean): CheckRecord {
  const q = s.byQuestion.get('q3')!;
  const names = Array.from({ length: q.max }, (_, i) => `a${i}`);
  return {
    question: 'q3',
    seed: q.seed,
    time: '2026-01-01T00:00:00Z',
    answers: names.map((name) => ({
      name,
      response: '1',
      verdict: correct ? 'correct' : 'incorrect',
      message: '',
    })),
    marks: { earned, total: q.max },
  };
}

/** A check as the launch page passes it on: recorded by the state, then reported. */
function check(s: ScormSession, r: CheckRecord): boolean {
  s.state.record(r);
  return s.onCheck(r);
}

describe('the score the LMS receives', () => {
  it('SCORM 1.2 and 2004: a worse later check keeps the best (page: best kept)', () => {
    for (const kind of ['scorm12', 'scorm2004'] as const) {
      const { win, d } = fakeLms(kind === 'scorm12' ? '1.2' : '2004', { 'cmi.core.student_id': 'ada' });
      const s = connectScorm(config(kind), win)!;
      const max = s.state.byQuestion.get('q3')!.max;
      expect(check(s, record(s.state, max, true))).toBe(true);
      check(s, record(s.state, max, false));
      if (kind === 'scorm12') {
        expect(d['cmi.core.score.raw']).toBe('100');
        expect(d['cmi.core.lesson_status']).toBe('passed');
      } else {
        expect(d['cmi.score.scaled']).toBe('1');
        expect(d['cmi.success_status']).toBe('passed');
      }
    }
  });
  it('all answers shown, then typed right: the LMS receives the page’s 0 marks, not full marks', () => {
    const { win, d } = fakeLms('2004', { 'cmi.learner_id': 'ada' });
    const s = connectScorm(config('scorm2004'), win)!;
    check(s, record(s.state, 0, true));
    expect(d['cmi.score.raw']).toBe('0');
    expect(d['cmi.success_status']).toBe('failed');
  });
  it('unreadable saved state on relaunch: a passed 100 stays passed 100', () => {
    for (const suspend of [
      '{"v":1,"q":',
      '{"v":2,"q":{}}',
      '{"v":1,"q":{"q3":{"s":999,"sc":8,"c":1}}}',
      'x',
    ]) {
      const { win, d } = fakeLms('1.2', {
        'cmi.core.student_id': 'ada',
        'cmi.core.score.raw': '100',
        'cmi.core.score.max': '100',
        'cmi.core.lesson_status': 'passed',
        'cmi.suspend_data': suspend,
      });
      const s = connectScorm(config('scorm12'), win)!;
      check(s, record(s.state, 0, false));
      expect(d['cmi.core.score.raw']).toBe('100');
      expect(d['cmi.core.lesson_status']).toBe('passed');
    }
    const { win, d } = fakeLms('2004', {
      'cmi.learner_id': 'ada',
      'cmi.score.scaled': '1',
      'cmi.completion_status': 'completed',
      'cmi.success_status': 'passed',
      'cmi.suspend_data': '{',
    });
    const s = connectScorm(config('scorm2004'), win)!;
    check(s, record(s.state, 1, false));
    expect(d['cmi.score.scaled']).toBe('1');
    expect(d['cmi.success_status']).toBe('passed');
    expect(d['cmi.completion_status']).toBe('completed');
  });
  it('a refused SetValue or Commit is reported as a failed check', () => {
    for (const v of ['1.2', '2004'] as const) {
      const { win } = fakeLms(v, {}, true);
      const s = connectScorm(config(v === '1.2' ? 'scorm12' : 'scorm2004'), win)!;
      expect(check(s, record(s.state, 1, true))).toBe(false);
    }
  });
  it('the state keeps the best marks through serialise and restore', () => {
    const s = new PracticeState(['q3'], 'ada', 1, 0.8);
    s.record(record(s, 3.3, true));
    s.record(record(s, 2, false));
    const back = new PracticeState(['q3'], 'ada', 1, 0.8);
    back.restore(s.serialise(4096));
    expect(back.byQuestion.get('q3')!.score).toBe(3.3);
  });
});
