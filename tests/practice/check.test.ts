/** The answer checker: numbers (tolerance, expressions, none), formulas (equivalence by the whitelisted compiler), choices. */
import { describe, expect, it } from 'vitest';
import {
  checkAnswer,
  checkFormula,
  classifyNumber,
  normaliseInput,
  parseNumberAnswer,
} from '../../src/practice/check';
import {
  allAnswers,
  type ChoiceAnswer,
  type FormulaAnswer,
  type NumberAnswer,
} from '../../src/practice/model';
import { QUESTIONS } from '../../src/practice/questions';
import { applyCheck, gradeAnswers, newSession } from '../../src/practice/session';
import { q1Variant } from '../../src/practice/q1';
import { q1Params, type Q1Params } from '../../src/practice/q1Density';

/** The first seed whose Q1 parameters satisfy `ok`. */
function seedWith(ok: (p: Q1Params) => boolean): number {
  let seed = 0;
  while (!ok(q1Params(seed))) seed++;
  return seed;
}

const numSpec: NumberAnswer = {
  kind: 'number',
  name: 'x',
  label: 'x',
  expected: 56 / 3,
  alternatives: [{ value: 10, message: 'flipped' }],
  mistakes: [{ id: 'no-div', value: 56 / 12, message: 'm' }],
};

describe('numbers', () => {
  it('reads numbers, constant expressions and none; rejects garbage with a message', async () => {
    expect(await parseNumberAnswer('18.67')).toMatchObject({
      ok: true,
      value: 18.67,
      exact: false,
      sigFigs: 4,
    });
    expect(await parseNumberAnswer(' none ')).toMatchObject({ ok: true, value: null });
    const e = await parseNumberAnswer('56/3');
    expect(e.ok && e.value).toBeCloseTo(56 / 3, 14);
    const k = await parseNumberAnswer('2/(e^(2π) − 1)');
    expect(k.ok && k.value).toBeCloseTo(2 / Math.expm1(2 * Math.PI), 15);
    for (const bad of ['', 'abc', '2*(3', '1,5', 'x+1', '1/0']) {
      const r = await parseNumberAnswer(bad);
      expect(r.ok, bad).toBe(false);
      if (!r.ok) expect(r.error.length).toBeGreaterThan(5);
    }
  });
  it('3 significant figures pass, 2 do not; alternatives correct with a note; mistakes named', async () => {
    expect((await checkAnswer(numSpec, '18.7')).value).toBe('correct');
    expect((await checkAnswer(numSpec, '18.6667')).value).toBe('correct');
    expect((await checkAnswer(numSpec, '19')).value).toBe('invalid');
    expect((await checkAnswer(numSpec, '17')).value).toBe('incorrect');
    expect((await checkAnswer(numSpec, '10')).message).toContain('flipped');
    expect((await checkAnswer(numSpec, '4.667')).value).toBe('mistake:no-div');
    expect((await checkAnswer(numSpec, 'none')).value).toBe('incorrect');
    expect(classifyNumber({ ...numSpec, expected: null }, null).value).toBe('correct');
    expect((await checkAnswer(numSpec, 'garbage')).value).toBe('invalid');
  });
});

describe('unreadable answers are never "none"', () => {
  const UNREADABLE = ['NaN', 'nan', '-', '—', '–', 'undefined', 'null', 'Infinity', '-Infinity'];
  it('NaN, a dash, undefined: unreadable, with a message saying what to type', async () => {
    for (const t of UNREADABLE) {
      const r = await parseNumberAnswer(t);
      expect(r.ok, t).toBe(false);
      if (!r.ok) expect(r.error, t).toContain('none');
      expect((await checkAnswer({ ...numSpec, expected: null }, t)).value, t).toBe('invalid');
    }
    // the words that do mean "does not exist" still do
    for (const t of ['none', 'None', 'no hit', 'n/a'])
      expect((await checkAnswer({ ...numSpec, expected: null }, t)).value, t).toBe('correct');
  });
  it('typing one of them in every box of any variant scores nothing (Q5 seed 11 once scored 3 with NaN)', async () => {
    for (const q of QUESTIONS)
      for (const seed of [1, 2, 3, 7, 11, 12]) {
        const v = q.generate(seed);
        for (const t of ['NaN', '-', 'undefined']) {
          const texts = Object.fromEntries(allAnswers(v).map((a) => [a.name, t]));
          const verdicts = Object.values(await gradeAnswers(v, texts));
          expect(
            verdicts.filter((x) => x.value === 'correct' || x.value === 'consistent'),
            `${q.id} seed ${seed}: ${t} everywhere`,
          ).toEqual([]);
        }
      }
  });
});

describe('formulas', () => {
  const spec: FormulaAnswer = {
    kind: 'formula',
    name: 'p-theta',
    label: 'p(θ)',
    variables: ['theta'],
    domain: [[0, Math.PI / 2]],
    expected: (t) => Math.sin(2 * t),
    expectedText: 'sin(2*theta)',
    alternatives: [],
    mistakes: [
      { id: 'inverted-jacobian', fns: [(t) => (2 * Math.cos(t)) / Math.sin(t)], message: 'inverted' },
    ],
  };
  it('accepts sin 2θ as 2 sin θ cos θ (and other equivalent forms), rejects near misses', async () => {
    for (const ok of [
      '2*sin(theta)*cos(theta)',
      'sin(2θ)'.replace('2θ', '2*θ'),
      '2 sin(θ) cos(θ)'.replace(/ /g, '*').replace('2*sin', '2*sin'),
      'sin(theta + theta)',
      '2*tan(theta)*cos(theta)^2',
    ]) {
      expect((await checkFormula(spec, ok)).value, ok).toBe('correct');
    }
    for (const bad of [
      '2.001*sin(theta)*cos(theta)',
      'sin(2*theta) + 0.0001',
      'sin(2.0001*theta)',
      'sin(theta)*cos(theta)',
      'cos(2*theta)',
    ]) {
      expect((await checkFormula(spec, bad)).value, bad).toBe('incorrect');
    }
    expect(
      (await checkFormula(spec, '2*cot(theta)'.replace('cot(theta)', 'cos(theta)/sin(theta)'))).value,
    ).toBe('mistake:inverted-jacobian');
  });
  it('the key’s first version 2·cot θ is read (cot, sec, csc are whitelisted) and named', async () => {
    expect((await checkFormula(spec, '2*cot(theta)')).value).toBe('mistake:inverted-jacobian');
    expect((await checkFormula(spec, '2/(sec(theta)*csc(theta))')).value).toBe('correct');
  });
  it('a decimal constant in a formula is read at its precision, as a number is', async () => {
    // Q1 with a = 1: p(φ) = e^φ/(e^(2π) − 1) = 0.00187094… e^φ
    const v = q1Variant(seedWith((p) => p.a.p === 1 && p.a.q === 1));
    const pPhi = allAnswers(v).find((a) => a.name === 'p-phi') as FormulaAnswer;
    const two = await checkFormula(pPhi, '0.0019*exp(phi)');
    expect(two.value).toBe('invalid');
    expect(two.message).toMatch(/0\.0019 has 2 significant figures: give at least 3/);
    expect((await checkFormula(pPhi, '0.00187*exp(phi)')).value).toBe('correct');
    expect((await checkFormula(pPhi, '0.001871*e^phi')).value).toBe('correct');
    expect((await checkFormula(pPhi, '0.001870*e^phi')).value).toBe('incorrect');
    expect((await checkFormula(pPhi, '0.00188*exp(phi)')).value).toBe('incorrect');
    // graded on the page: asked for more figures, so the attempt is not counted
    const verdicts = await gradeAnswers(v, { 'p-phi': '0.0019*exp(phi)' });
    expect(verdicts['p-phi']?.value).toBe('invalid');
    const s = applyCheck(v, newSession(v), { 'p-phi': '0.0019*exp(phi)' }, verdicts);
    expect(s.parts.b.attempts).toBe(0);
    expect(s.parts.b.wrong).toBe(0);
  });
  it('bad syntax and unknown names are invalid with a message', async () => {
    for (const bad of ['sin(theta', 'x^2', 'foo(theta)', 'theta = 1', '']) {
      const r = await checkFormula(spec, bad);
      expect(r.value, bad).toBe('invalid');
      expect(r.message.length).toBeGreaterThan(10);
    }
  });
  it('normalises what people type', () => {
    expect(normaliseInput('ln(1 + ξ₂)')).toBe('log(1 + xi)');
    expect(normaliseInput('arccos(1 − 2ξ1)/2')).toBe('acos(1 - 2xi)/2');
    expect(normaliseInput('2·sin(θ)×cos(θ)')).toBe('2*sin(θ)*cos(θ)');
  });
});

describe('choices', () => {
  it('exact option names (spaces as hyphens), others invalid', async () => {
    const c: ChoiceAnswer = {
      kind: 'choice',
      name: 'case',
      label: 'case',
      options: ['miss', 'two-hits', 'inside'],
      expected: 'inside',
      mistakes: [{ id: 'ignored-t-sign', value: 'two-hits', message: 'm' }],
      why: 'w',
    };
    expect((await checkAnswer(c, 'Inside')).value).toBe('correct');
    expect((await checkAnswer(c, 'two hits')).value).toBe('mistake:ignored-t-sign');
    expect((await checkAnswer(c, 'miss')).value).toBe('incorrect');
    expect((await checkAnswer(c, 'sideways')).value).toBe('invalid');
  });
});
