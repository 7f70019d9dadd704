import { describe, expect, it } from 'vitest';
import { PracticeState } from '../../src/lms/state';
import { learnerSeed } from '../../src/lms/seeds';
import { time12, time2004 } from '../../src/lms/scorm';
import { QUESTION_IDS } from '../../src/practice/model';

describe('LMS learner state', () => {
  it('derives stable, learner-specific seeds', () => {
    const a = new PracticeState(QUESTION_IDS, 'alice', 3, 0.8);
    const a2 = new PracticeState(QUESTION_IDS, 'alice', 3, 0.8);
    const b = new PracticeState(QUESTION_IDS, 'bob', 3, 0.8);
    const seeds = (s: PracticeState) => [...s.byQuestion.values()].map((x) => x.seed);
    expect(seeds(a)).toEqual(seeds(a2));
    expect(seeds(a)).not.toEqual(seeds(b));
    expect(learnerSeed('alice', 'q1', 3)).not.toBe(learnerSeed('alice', 'q1', 4));
  });

  it('keeps suspend data within the limit, scores first', () => {
    const s = new PracticeState(QUESTION_IDS, 'carol', 1, 0.8);
    for (const [q, e] of s.byQuestion) {
      e.answers = { x: 'y'.repeat(900), z: `${q}-short` };
      e.score = 2;
      e.checked = true;
    }
    const text = s.serialise(4096);
    expect(text.length).toBeLessThanOrEqual(4096);
    const back = new PracticeState(QUESTION_IDS, 'carol', 1, 0.8);
    expect(back.restore(text)).toBe(true);
    for (const [q, e] of back.byQuestion) {
      expect(e.score).toBe(2);
      expect(e.checked).toBe(true);
      expect(e.answers.z).toBe(`${q}-short`);
    }
    // another learner's data does not apply (other seeds)
    const other = new PracticeState(QUESTION_IDS, 'dave', 1, 0.8);
    other.restore(text);
    expect([...other.byQuestion.values()].every((e) => !e.checked)).toBe(true);
  });

  it('totals: incomplete until every question is checked, then passed or failed', () => {
    const s = new PracticeState(['q3', 'q5'], 'erin', 0, 0.8);
    expect(s.totals().complete).toBe(false);
    for (const e of s.byQuestion.values()) {
      e.checked = true;
      e.score = e.max;
    }
    expect(s.totals()).toMatchObject({ complete: true, passed: true, scaled: 1 });
    s.byQuestion.get('q3')!.score = 0;
    expect(s.totals().passed).toBe(false);
  });

  it('formats SCORM times', () => {
    expect(time12(3_723_450)).toBe('0001:02:03.45');
    expect(time2004(3_723_450)).toBe('PT1H2M3.45S');
  });
});
