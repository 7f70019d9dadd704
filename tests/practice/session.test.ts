/**
 * One part at a time: Check grades only what is typed; attempts are counted per part; marks follow
 * the stated policy (10 % off per earlier wrong attempt, best counts, nothing after Show answer);
 * a part's answer is shown after 3 wrong attempts.
 */
import { describe, expect, it } from 'vitest';
import { q4Variant } from '../../src/practice/q4';
import { allAnswers, type NumberAnswer } from '../../src/practice/model';
import {
  applyCheck,
  gradeAnswers,
  newSession,
  revealPart,
  SCORING,
  sessionScore,
  type Session,
} from '../../src/practice/session';

const v = q4Variant(21);
const spec = (name: string) => allAnswers(v).find((a) => a.name === name) as NumberAnswer;
const exact = () => String(spec('exact').expected);
const uniform = () => String(spec('uniform').expected);

async function check(s: Session, texts: Record<string, string>): Promise<Session> {
  return applyCheck(v, s, texts, await gradeAnswers(v, texts));
}

describe('practice session', () => {
  it('grades only what is typed; an unanswered part has no verdict and no attempt', async () => {
    const texts = { exact: exact() };
    const verdicts = await gradeAnswers(v, texts);
    expect(Object.keys(verdicts)).toEqual(['exact']);
    const s = applyCheck(v, newSession(v), texts, verdicts);
    expect(s.parts.a.attempts).toBe(1);
    expect(s.parts.b.attempts).toBe(0);
    expect(s.answers.uniform.verdict).toBeNull();
    expect(s.answers.exact.best).toBe(1);
  });
  it('10 % off per earlier wrong attempt, best counts, unchanged text is not a new attempt', async () => {
    let s = newSession(v);
    s = await check(s, { uniform: '1' }); // wrong
    s = await check(s, { uniform: '1' }); // same text: not counted again
    expect(s.parts.b.attempts).toBe(1);
    s = await check(s, { uniform: '2' }); // wrong again
    s = await check(s, { uniform: uniform() });
    expect(s.parts.b).toMatchObject({ attempts: 3, wrong: 2 });
    expect(s.answers.uniform.best).toBeCloseTo(1 - 2 * SCORING.penalty, 12);
    s = await check(s, { uniform: '3' }); // a later wrong attempt keeps the best
    expect(s.answers.uniform.best).toBeCloseTo(0.8, 12);
    expect(s.parts.b.revealed).toBe('attempts'); // 3 wrong attempts: the answer is shown
  });
  it('invalid input is not an attempt; Show answer ends the marks for that part', async () => {
    let s = newSession(v);
    s = await check(s, { exact: '2*(3' });
    expect(s.parts.a.attempts).toBe(0);
    expect(s.answers.exact.verdict?.value).toBe('invalid');
    s = revealPart(s, 'a');
    s = await check(s, { exact: exact() });
    expect(s.answers.exact.verdict?.value).toBe('correct');
    expect(s.answers.exact.best).toBe(0);
    expect(sessionScore(v, s)).toEqual({ marks: 0, total: 3 });
  });
});
