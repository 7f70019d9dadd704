/**
 * A practice Check as the page records it, for the LMS runtime tests: the question's variant for
 * `seed`, its first `right` answers typed right and the rest wrong, with the page's marks and the
 * parts whose answers were shown (forfeited).
 */
import { variantOf } from '../../src/lms/grade';
import { expectedText } from '../../src/practice/check';
import { allAnswers, type QuestionId } from '../../src/practice/model';
import type { CheckRecord } from '../../src/practice/extensions';

export function checkRecord(
  question: QuestionId,
  seed: number,
  right: number,
  marks?: number,
  shown = false,
): CheckRecord {
  const answers = allAnswers(variantOf(question, seed));
  return {
    question,
    seed,
    time: '2026-01-01T00:00:00Z',
    answers: answers.map((a, i) => ({
      name: a.name,
      response: i < right ? expectedText(a) : '12345',
      verdict: i < right ? 'correct' : 'incorrect',
      message: '',
    })),
    marks: marks === undefined ? undefined : { earned: marks, total: answers.length },
    forfeited: shown ? answers.map((a) => a.name) : undefined,
  };
}
