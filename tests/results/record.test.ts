/** The results log: a merge on every write (two tabs), per learner, cleared by Reset progress. */
import { describe, expect, it } from 'vitest';
import {
  appendAttempt,
  attemptOf,
  loadAttempts,
  loadName,
  RESULTS_KEY,
  saveName,
  startRecording,
} from '../../src/results/record';
import { extensionCheck } from '../../src/practice/extensions';
import { resetPractice } from '../../src/practice/reset';
import { setLearnerScope } from '../../src/practice/learnerScope';
import { collate } from '../../src/results/collate';
import { freshWindowEachTest } from '../practice/memoryWindow';
import type { Attempt } from '../../src/results/format';

const storage = freshWindowEachTest();

const at = (seed: number, time: string): Attempt => ({
  question: 'q3',
  seed,
  time,
  answers: { x: String(seed) },
  verdicts: { x: 'incorrect' },
});

describe('results log', () => {
  it('two tabs: each write keeps the other tab’s checks', () => {
    appendAttempt(at(1, '2026-01-01T00:00:01Z'));
    // tab B wrote in between (its own copy of the log plus its check)
    const other = JSON.parse(storage.local.getItem(RESULTS_KEY)!) as { attempts: Attempt[] };
    other.attempts.push(at(2, '2026-01-01T00:00:02Z'));
    storage.local.setItem(RESULTS_KEY, JSON.stringify(other));
    appendAttempt(at(3, '2026-01-01T00:00:03Z'));
    expect(loadAttempts().map((a) => a.seed)).toEqual([1, 2, 3]);
    // the same attempt written twice is kept once
    appendAttempt(at(3, '2026-01-01T00:00:03Z'));
    expect(loadAttempts()).toHaveLength(3);
  });
  it('Reset progress clears the log and the name', () => {
    startRecording();
    saveName('Ada');
    extensionCheck({
      question: 'q3',
      seed: 4,
      time: '2026-01-01T00:00:00Z',
      answers: [{ name: 'x', response: '1', verdict: 'incorrect', message: '' }],
    });
    expect(loadAttempts()).toHaveLength(1);
    resetPractice();
    expect(loadAttempts()).toHaveLength(0);
    expect(loadName()).toBe('');
  });
  it('per learner inside an LMS package: the next learner sees no checks and no name', () => {
    setLearnerScope('learner-1');
    saveName('Ada');
    appendAttempt(at(5, '2026-01-01T00:00:05Z'));
    setLearnerScope('learner-2');
    expect(loadAttempts()).toHaveLength(0);
    expect(loadName()).toBe('');
  });
  it('a check after Show answer is logged with its forfeits, and #/results scores them 0', async () => {
    const { questionInfo } = await import('../../src/practice/questions');
    const { allAnswers } = await import('../../src/practice/model');
    const { expectedText } = await import('../../src/practice/check');
    const v = questionInfo('q3').generate(11);
    const answers = allAnswers(v).map((a) => ({
      name: a.name,
      response: expectedText(a),
      verdict: 'correct',
      message: '',
    }));
    const all = allAnswers(v).map((a) => a.name);
    const a = attemptOf({ question: 'q3', seed: 11, time: 't', answers, forfeited: all });
    const file = { format: 'render-math-lab-results', formatVersion: 1, student: 'Ada', attempts: [a] };
    const c = await collate([{ name: 'ada.json', text: JSON.stringify(file) }]);
    expect(c.students[0].best.q3?.score).toBe(0);
    const honest = { ...file, attempts: [{ ...a, forfeited: undefined }] };
    const c2 = await collate([{ name: 'ada.json', text: JSON.stringify(honest) }]);
    expect(c2.students[0].best.q3?.score).toBe(all.length);
  });
});
