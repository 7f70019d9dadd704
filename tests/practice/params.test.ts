/** The practice pages' URL contract: their schemas, read by the kit's parser, bad values named. */
import { describe, expect, it } from 'vitest';
import { parseQuestionParams, parseSheetParams } from '../../src/practice/params';

const sp = (q: string) => new URLSearchParams(q);
const names = (ps: { name: string }[]) => ps.map((p) => p.name);

describe('question page', () => {
  it('a valid seed is the variant, as given', () => {
    expect(parseQuestionParams(sp('seed=17'), 5)).toEqual({ seed: 17, seedAsGiven: true, problems: [] });
    expect(parseQuestionParams(sp('seed=4294967295'), 5).seed).toBe(4294967295);
  });

  it('no seed: the fallback (a fresh variant), quietly, to be written into the URL', () => {
    expect(parseQuestionParams(sp(''), 5)).toEqual({ seed: 5, seedAsGiven: false, problems: [] });
  });

  it.each([
    ['seed=banana', 5, /"banana" is not a finite number; using the default 5/],
    ['seed=', 5, /is not a finite number; using the default 5/],
    ['seed=-3', 0, /outside \[0, 4294967295\]; using 0/],
    ['seed=99999999999', 4294967295, /outside \[0, 4294967295\]; using 4294967295/],
    ['seed=2.5', 3, /not a whole number; using 3/],
    ['seed=0x10', 5, /not a finite number; using the default 5/],
  ])('a malformed seed (%s) is named, with the value used instead', (q, seed, re) => {
    const r = parseQuestionParams(sp(q), 5);
    expect(r.seed).toBe(seed);
    expect(r.seedAsGiven).toBe(false);
    expect(names(r.problems)).toEqual(['seed']);
    expect(r.problems[0].message).toMatch(re);
  });

  it('other parameters are named as not taken; shell ones are left to the shell', () => {
    const r = parseQuestionParams(sp('seed=3&colour=red&embed=1&seed=4'), 5);
    expect(r.seed).toBe(3);
    expect(names(r.problems).sort()).toEqual(['colour', 'seed']);
    expect(r.problems.find((p) => p.name === 'seed')!.message).toMatch(/more than once; using the first/);
  });
});

describe('worksheet', () => {
  it('defaults: seed 1, all six questions, one variant each, no solutions', () => {
    expect(parseSheetParams(sp(''))).toEqual({
      seed: 1,
      qs: ['q1', 'q2', 'q3', 'q4', 'q5', 'q6'],
      count: 1,
      solutions: false,
      problems: [],
    });
  });

  it('reads a valid link', () => {
    const r = parseSheetParams(sp('seed=42&q=5,1,5&count=3&solutions=1'));
    expect(r).toEqual({ seed: 42, qs: ['q5', 'q1'], count: 3, solutions: true, problems: [] });
  });

  it.each([
    ['seed=x', 'seed', { seed: 1 }],
    ['q=a,b', 'q', { qs: ['q1', 'q2', 'q3', 'q4', 'q5', 'q6'] }],
    ['q=1,9', 'q', { qs: ['q1', 'q6'] }],
    ['q=2.4', 'q', { qs: ['q2'] }],
    ['count=0', 'count', { count: 1 }],
    ['count=50', 'count', { count: 10 }],
    ['count=two', 'count', { count: 1 }],
    ['solutions=maybe', 'solutions', { solutions: false }],
  ])('a bad value (%s) is named and replaced', (q, name, expected) => {
    const r = parseSheetParams(sp(q));
    expect(r).toMatchObject(expected);
    expect(names(r.problems)).toContain(name);
    for (const p of r.problems) expect(p.message.length).toBeGreaterThan(10);
  });
});
