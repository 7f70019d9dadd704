import { describe, expect, it } from 'vitest';
import { collate } from '../../src/results/collate';
import { studentsCsv } from '../../src/results/csv';
import { parseResultsFile, RESULTS_FORMAT } from '../../src/results/format';
import { variantOf } from '../../src/lms/grade';
import { expectedText } from '../../src/practice/check';
import { allAnswers } from '../../src/practice/model';

function file(student: string, attempts: unknown[]) {
  return JSON.stringify({
    format: RESULTS_FORMAT,
    formatVersion: 1,
    app: 't',
    student,
    created: '',
    attempts,
  });
}

describe('class results', () => {
  const v = variantOf('q5', 123);
  const answers = allAnswers(v);
  const right = Object.fromEntries(answers.map((a) => [a.name, expectedText(a)]));
  const wrong = answers.find((a) => a.kind === 'number' && a.mistakes.length)!;
  const m = wrong.kind === 'number' ? wrong.mistakes[0] : null!;

  it('regrades from seed and typed answers: an edited verdict cannot raise the score', async () => {
    const edited = { ...right, [wrong.name]: String(m.value) };
    const allCorrect = Object.fromEntries(answers.map((a) => [a.name, 'correct']));
    const c = await collate([
      {
        name: 'a.json',
        text: file('Ada', [{ question: 'q5', seed: 123, answers: edited, verdicts: allCorrect }]),
      },
      { name: 'b.json', text: file('', [{ question: 'q5', seed: 123, answers: right, verdicts: {} }]) },
      { name: 'c.json', text: '{"nope": 1}' },
      { name: 'd.json', text: 'garbage' },
    ]);
    expect(c.students.map((s) => s.student)).toEqual(['Ada', 'b']);
    expect(c.students[0].best.q5).toMatchObject({ score: answers.length - 1, max: answers.length });
    expect(c.students[1].best.q5).toMatchObject({ score: answers.length, max: answers.length });
    const q5 = c.questions.find((q) => q.question === 'q5')!;
    expect(q5.mistakes[m.id]).toBe(1);
    expect(q5.disagreements).toBe(1);
    expect(q5.meanBest).toBeCloseTo((2 * answers.length - 1) / (2 * answers.length), 9);
    expect(c.problems).toHaveLength(2);
    const csv = studentsCsv(c).split('\r\n');
    expect(csv[0]).toContain('q5 score');
    expect(csv[1]).toContain(`Ada,a.json,1,`);
    expect(csv[1]).toContain(`,${answers.length - 1},${answers.length}`);
  });

  it('rejects attempts that name no question or seed, and bounds the text', () => {
    const p = parseResultsFile(
      file('x', [
        { question: 'q9', seed: 1 },
        { question: 'q1', seed: -1 },
        { question: 'q1', seed: 2, answers: { k: 'y'.repeat(5000), bad: 3 } },
      ]),
    );
    expect(p.ok).toBe(true);
    if (!p.ok) return;
    expect(p.skipped).toBe(2);
    expect(p.file.attempts[0].answers.k).toHaveLength(500);
    expect(p.file.attempts[0].answers.bad).toBeUndefined();
  });
});
