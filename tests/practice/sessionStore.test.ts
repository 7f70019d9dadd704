/** A variant's marking state survives reloads and other tabs: forfeits, attempts and best marks. */
import { describe, expect, it } from 'vitest';
import { questionInfo } from '../../src/practice/questions';
import { allAnswers, type Variant } from '../../src/practice/model';
import { expectedText } from '../../src/practice/check';
import { applyCheck, gradeAnswers, revealPart, sessionScore } from '../../src/practice/session';
import { loadSession, saveSession, withStored } from '../../src/practice/sessionStore';
import { SESSIONS_KEY } from '../../src/practice/sessionKey';
import { resetPractice } from '../../src/practice/reset';
import { loadScores, recordScore } from '../../src/practice/scores';
import { setLearnerScope } from '../../src/practice/learnerScope';
import { freshWindowEachTest } from './memoryWindow';

const storage = freshWindowEachTest();

function rightAnswers(v: Variant): Record<string, string> {
  return Object.fromEntries(allAnswers(v).map((a) => [a.name, expectedText(a)]));
}

/** A page that opens the variant (reload = a new page), applies a check as the page does. */
async function check(v: Variant, texts: Record<string, string>) {
  const before = withStored(v, loadSession(v));
  const next = applyCheck(v, before, texts, await gradeAnswers(v, texts));
  saveSession(v, next);
  return sessionScore(v, next);
}

describe('marking state kept across reloads', () => {
  const v = questionInfo('q3').generate(11);
  it('Show answer, reload, type the answers, Check: the shown part earns nothing', async () => {
    const shown = v.parts[0];
    saveSession(v, revealPart(loadSession(v), shown.id));
    // a reload: a new page reads the session back
    expect(loadSession(v).parts[shown.id].revealed).toBe('asked');
    const score = await check(v, rightAnswers(v));
    expect(score.marks).toBe(score.total - shown.answers.length);
  });
  it('Show all answers, then the same answers typed: 0 marks, also after a reload', async () => {
    saveSession(
      v,
      v.parts.reduce((s, p) => revealPart(s, p.id), loadSession(v)),
    );
    expect((await check(v, rightAnswers(v))).marks).toBe(0);
    expect((await check(v, { ...rightAnswers(v) })).marks).toBe(0);
  });
  it('attempts and the best mark survive a reload, and a worse later check keeps the best', async () => {
    const right = rightAnswers(v);
    const first = await check(v, right);
    expect(first.marks).toBe(first.total);
    const wrong = Object.fromEntries(Object.keys(right).map((k) => [k, '12345']));
    const later = await check(v, wrong);
    expect(later.marks).toBe(first.total);
    expect(Object.values(loadSession(v).parts).every((p) => p.attempts === 2)).toBe(true);
  });
  it('two tabs: a reveal in one is kept when the other saves its stale session', () => {
    const tabA = loadSession(v);
    const tabB = loadSession(v);
    saveSession(v, revealPart(tabA, v.parts[1].id));
    const merged = saveSession(v, tabB);
    expect(merged.parts[v.parts[1].id].revealed).toBe('asked');
    expect(loadSession(v).parts[v.parts[1].id].revealed).toBe('asked');
  });
  it('junk under the key reads as a new session and is replaced on save', () => {
    for (const junk of ['{', '[]', '{"q3:11":{"p":{"x":[1e9,"a",3,9]},"a":5}}', 'null']) {
      storage.local.setItem(SESSIONS_KEY, junk);
      const s = loadSession(v);
      expect(Object.values(s.parts).every((p) => p.attempts === 0 && p.revealed === null)).toBe(true);
      saveSession(v, revealPart(s, v.parts[0].id));
      expect(loadSession(v).parts[v.parts[0].id].revealed).toBe('asked');
    }
  });
  it('Reset progress forgets the marking state and the best marks', () => {
    saveSession(v, revealPart(loadSession(v), v.parts[0].id));
    recordScore('q3', 11, 0.5);
    resetPractice();
    expect(loadSession(v).parts[v.parts[0].id].revealed).toBe(null);
    expect(loadScores().q3['11']).toBeUndefined();
  });
  it('inside an LMS package each learner has their own state, under a hashed key', () => {
    setLearnerScope('mailto:ada@example.org');
    saveSession(v, revealPart(loadSession(v), v.parts[0].id));
    recordScore('q3', 11, 0.75);
    setLearnerScope('mailto:bob@example.org');
    expect(loadSession(v).parts[v.parts[0].id].revealed).toBe(null);
    expect(loadScores().q3['11']).toBeUndefined();
    setLearnerScope('mailto:ada@example.org');
    expect(loadSession(v).parts[v.parts[0].id].revealed).toBe('asked');
    expect([...storage.local.data.keys()].join(' ')).not.toMatch(/ada|example/);
  });
});
