/**
 * Held-out orders for the kept practice data: two tabs that check in turn with stale copies, a
 * shared lab computer with two LMS learners, and a relaunch whose tab kept a newer draft than the
 * LMS.
 */
import { describe, expect, it } from 'vitest';
import { questionInfo } from '../../src/practice/questions';
import { allAnswers, type Variant } from '../../src/practice/model';
import { expectedText } from '../../src/practice/check';
import { applyCheck, gradeAnswers, revealPart, sessionScore, type Session } from '../../src/practice/session';
import { loadSession, saveSession, withStored } from '../../src/practice/sessionStore';
import { loadDraft, openingAnswers, saveDraft } from '../../src/practice/drafts';
import { setLearnerScope } from '../../src/practice/learnerScope';
import { resetPractice } from '../../src/practice/reset';
import { appendAttempt, loadAttempts, loadName, resultsFile, saveName } from '../../src/results/record';
import { freshWindowEachTest } from './memoryWindow';

const storage = freshWindowEachTest();

const v: Variant = questionInfo('q5').generate(29);
const right = () => Object.fromEntries(allAnswers(v).map((a) => [a.name, expectedText(a)]));
/** Wrong answers, different each time (an unchanged answer is not a new attempt). */
const wrong = (k = 0) => Object.fromEntries(allAnswers(v).map((a) => [a.name, String(12345 + k)]));

/** A tab: its own session in memory, checked as the page does (merged with what is kept first). */
class Tab {
  s: Session = loadSession(v);
  async check(texts: Record<string, string>) {
    const before = withStored(v, this.s);
    this.s = saveSession(v, applyCheck(v, before, texts, await gradeAnswers(v, texts)));
    return sessionScore(v, this.s);
  }
  reveal(i: number) {
    this.s = saveSession(v, revealPart(this.s, v.parts[i].id));
  }
}

describe('two tabs on one variant', () => {
  it('a full mark in one tab is kept when the other, stale, checks worse', async () => {
    const a = new Tab();
    const b = new Tab();
    const full = await a.check(right());
    const later = await b.check(wrong());
    expect(later.marks).toBe(full.total);
    expect(sessionScore(v, loadSession(v)).marks).toBe(full.total);
  });
  it('an answer shown in one tab earns nothing when the other, stale, checks it right', async () => {
    const a = new Tab();
    const b = new Tab();
    a.reveal(0);
    const score = await b.check(right());
    expect(score.marks).toBe(score.total - v.parts[0].answers.length);
    // and after a reload of either
    expect(sessionScore(v, new Tab().s).marks).toBe(score.total - v.parts[0].answers.length);
  });
  it('attempts counted in either tab are not lost when the other saves', async () => {
    const a = new Tab();
    const b = new Tab();
    await a.check(wrong(1));
    await a.check(wrong(2));
    await b.check(wrong(3));
    expect(Math.min(...Object.values(loadSession(v).parts).map((p) => p.attempts))).toBeGreaterThanOrEqual(2);
  });
});

describe('a shared lab computer', () => {
  it('the next learner gets none of the previous one’s checks, name, marks or drafts', async () => {
    setLearnerScope('https://lms.test|ada');
    saveName('Ada');
    appendAttempt({ question: 'q5', seed: 29, time: 't1', answers: { a: '1' }, verdicts: {} });
    await new Tab().check(right());
    saveDraft('q5', 29, { a: '0.5' });
    setLearnerScope('https://lms.test|bob');
    expect(loadName()).toBe('');
    expect(loadAttempts()).toEqual([]);
    expect(resultsFile('Bob').attempts).toEqual([]);
    expect(sessionScore(v, loadSession(v)).marks).toBe(0);
    expect(loadDraft('q5', 29)).toEqual({});
    // Bob's Reset clears Bob's data only; Ada's is there when she returns
    resetPractice();
    setLearnerScope('https://lms.test|ada');
    expect(loadName()).toBe('Ada');
    expect(loadAttempts()).toHaveLength(1);
    // nothing stored names the learner
    expect([...storage.local.data.keys(), ...storage.session.data.keys()].join(' ')).not.toMatch(
      /ada|bob|lms\.test/i,
    );
  });
});

describe('a relaunch after a crash', () => {
  it('opens with the tab’s draft, typed after what the LMS kept', () => {
    const kept = { a: '1' };
    saveDraft('q5', 29, { a: '1', b: '2', c: '3', discriminant: '4' });
    expect(openingAnswers('q5', 29, () => kept)).toEqual({ a: '1', b: '2', c: '3', discriminant: '4' });
    // a new tab (no draft) opens with what the LMS kept; an empty draft does not hide it
    storage.session.data.clear();
    expect(openingAnswers('q5', 29, () => kept)).toEqual(kept);
    saveDraft('q5', 29, { a: '' });
    expect(openingAnswers('q5', 29, () => kept)).toEqual(kept);
  });
});
