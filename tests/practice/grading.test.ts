/**
 * Grading that a near miss cannot fool, checked over thousands of seeds of every question
 * (fast-check, seeded): every named mistake typed exactly is never correct and is named; the
 * correct answer typed exactly, and rounded to 3 and to 6 significant figures, is correct.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { QUESTIONS } from '../../src/practice/questions';
import { q1Variant } from '../../src/practice/q1';
import { q1Params } from '../../src/practice/q1Density';
import { allAnswers, type NumberAnswer, type Variant } from '../../src/practice/model';
import {
  checkAnswer,
  checkChoice,
  classifyFormula,
  parseNumberAnswer,
  checkNumber,
} from '../../src/practice/check';
import { decimalPrecision } from '../../src/practice/decimals';

const RUNS = 3000;

function numberTexts(x: number): { exact: string[]; rounded: string[] } {
  return { exact: [String(x), `(${String(x)})*1`], rounded: [x.toPrecision(3), x.toPrecision(6)] };
}

async function failuresOf(v: Variant): Promise<string[]> {
  const bad: string[] = [];
  for (const a of allAnswers(v)) {
    const where = `${v.question} seed ${v.seed} ${a.name}`;
    if (a.kind === 'number') {
      if (a.expected === null) {
        if ((await checkNumber(a, 'none')).value !== 'correct') bad.push(`${where}: none not correct`);
      } else {
        const t = numberTexts(a.expected);
        for (const s of [...t.exact, ...t.rounded]) {
          const got = (await checkNumber(a, s)).value;
          if (got !== 'correct') bad.push(`${where}: correct answer typed ${s} gave ${got}`);
        }
      }
      for (const m of a.mistakes) {
        for (const s of numberTexts(m.value).exact) {
          const got = (await checkNumber(a, s)).value;
          if (got !== `mistake:${m.id}`) bad.push(`${where}: mistake ${m.id} typed ${s} gave ${got}`);
        }
      }
    } else if (a.kind === 'formula') {
      const got = (await checkAnswer(a, a.expectedText)).value;
      if (got !== 'correct') bad.push(`${where}: expected formula ${a.expectedText} gave ${got}`);
      for (const m of a.mistakes)
        for (const fn of m.fns) {
          const g = classifyFormula(a, fn).value;
          if (g !== `mistake:${m.id}`) bad.push(`${where}: formula mistake ${m.id} gave ${g}`);
        }
    } else {
      if (checkChoice(a, a.expected).value !== 'correct') bad.push(`${where}: choice`);
      for (const m of a.mistakes)
        if (checkChoice(a, m.value).value !== `mistake:${m.id}`) bad.push(`${where}: choice ${m.id}`);
    }
  }
  return bad;
}

describe.each(QUESTIONS.map((q) => [q.id, q] as const))('%s grading', (_id, q) => {
  it(`${RUNS} seeds: mistakes typed exactly are named, never correct; the answer exact and rounded is correct`, async () => {
    const seeds = fc.sample(fc.integer({ min: 0, max: 0xffffffff }), { numRuns: RUNS, seed: 23 + q.n });
    const bad: string[] = [];
    for (const s of seeds) {
      bad.push(...(await failuresOf(q.generate(s))));
      if (bad.length > 10) break;
    }
    expect(bad.slice(0, 10)).toEqual([]);
  }, 240_000);
});

describe('near misses of the normalization constant', () => {
  it('q1 seed 8: 3/e^(3*pi) (the e⁰ term forgotten) is named, never correct', async () => {
    const v = q1Variant(8);
    expect(q1Params(8)).toMatchObject({ m: 1, a: { p: 3, q: 2 } });
    const k = allAnswers(v).find((a) => a.name === 'k') as NumberAnswer;
    expect((await checkNumber(k, '3/e^(3*pi)')).value).toBe('mistake:forgot-e0');
    expect((await checkNumber(k, '3/(e^(3*pi) - 1)')).value).toBe('correct');
    // 3/e^(3π) typed to 4 figures is still (to 4 figures) the right answer too: marked correct, with a note
    const four = await checkNumber(k, k.expected!.toPrecision(4));
    expect(four.value).toBe('correct');
  });
  it('the exam’s own k = 2/(e^(2π) − 1): 2/e^(2*pi) is named', async () => {
    let seed = 0;
    while (!(q1Params(seed).m === 1 && q1Params(seed).a.p === 1 && q1Params(seed).a.q === 1)) seed++;
    const k = allAnswers(q1Variant(seed)).find((a) => a.name === 'k') as NumberAnswer;
    expect((await checkNumber(k, '2/e^(2*pi)')).value).toBe('mistake:forgot-e0');
    expect((await checkNumber(k, '2/(e^(2*pi)-1)')).value).toBe('correct');
    expect((await checkNumber(k, '0.003735')).value).toBe('mistake:forgot-e0');
    expect((await checkNumber(k, '0.00374')).value).toBe('correct');
  });
});

describe('decimals are read at the precision they were typed to', () => {
  it('half a unit in the last digit; leading zeros are not significant', () => {
    expect(decimalPrecision('0.00374').sigFigs).toBe(3);
    expect(decimalPrecision('0.00374').halfUnit).toBeCloseTo(0.5e-5, 20);
    expect(decimalPrecision('3.740e-3').sigFigs).toBe(4);
    expect(decimalPrecision('3.740e-3').halfUnit).toBeCloseTo(0.5e-6, 20);
    expect(decimalPrecision('1200')).toEqual({ halfUnit: 0.5, sigFigs: 4 });
    expect(decimalPrecision('0.0120').sigFigs).toBe(3);
    expect(decimalPrecision('-18.67').sigFigs).toBe(4);
    expect(decimalPrecision('.5')).toEqual({ halfUnit: 0.05, sigFigs: 1 });
  });
  const spec: NumberAnswer = {
    kind: 'number',
    name: 'x',
    label: 'x',
    expected: 56 / 3,
    alternatives: [],
    mistakes: [{ id: 'near', value: 18.672, message: 'near' }],
  };
  it('3 figures at least; the correct rounding passes; a wrong last digit does not', async () => {
    expect((await checkNumber(spec, '18.7')).value).toBe('correct');
    expect((await checkNumber(spec, '18.7')).message).toContain('also what the mistake');
    expect((await checkNumber(spec, '18.6667')).value).toBe('correct');
    expect((await checkNumber(spec, '18.6')).value).toBe('incorrect');
    expect((await checkNumber(spec, '18.6')).message).toContain('Close');
    expect((await checkNumber(spec, '19')).value).toBe('invalid');
    expect((await checkNumber(spec, '19')).message).toContain('significant figure');
    expect((await checkNumber(spec, '18.672')).value).toBe('mistake:near');
    expect((await checkNumber(spec, '18.67')).value).toBe('correct');
    expect((await checkNumber(spec, '56/3 + 1e-6')).value).toBe('incorrect');
    expect((await checkNumber(spec, '2')).value).toBe('incorrect');
  });
  it('an exact whole number needs no figures; none and garbage', async () => {
    const four: NumberAnswer = { ...spec, expected: 4, mistakes: [] };
    expect((await checkNumber(four, '4')).value).toBe('correct');
    expect((await checkNumber(four, '4.0001')).value).toBe('incorrect');
    expect((await parseNumberAnswer('1,5')).ok).toBe(false);
  });
});
