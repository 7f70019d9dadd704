/**
 * Follow-through on constructed wrong chains: a later answer that is right for the student's own
 * wrong earlier answer is `consistent` (and says which answer was wrong), earns the stated partial
 * credit, and is not confused with a right answer or with an answer right for nothing.
 */
import { describe, expect, it } from 'vitest';
import { q1Variant } from '../../src/practice/q1';
import { q1Params } from '../../src/practice/q1Density';
import { q3Variant } from '../../src/practice/q3';
import { q4Params, q4Variant, q4Functions } from '../../src/practice/q4';
import { q5Variant } from '../../src/practice/q5';
import { q6Variant } from '../../src/practice/q6';
import { allAnswers, type NumberAnswer, type Variant } from '../../src/practice/model';
import { applyCheck, gradeAnswers, newSession, SCORING } from '../../src/practice/session';
import { sphericalUV, bilinear, EXAM_LOOKUP, parseGrid } from '../../src/core/texture';

const num = (v: Variant, name: string) =>
  (allAnswers(v).find((a) => a.name === name) as NumberAnswer).expected;
const g = (v: Variant, name: string) => v.givens.find((x) => x.name === name)!.value;

describe('Q1 follow-through', () => {
  const v = q1Variant(8); // p = k cos θ e^(3φ/2)
  it('the setting is the issue’s seed 8', () =>
    expect(q1Params(8)).toMatchObject({ m: 1, a: { p: 3, q: 2 } }));
  it('p(φ) from a wrong k, P(θ) from a wrong p(θ), θ(ξ) from a wrong P(θ)', async () => {
    const texts = {
      k: '3/e^(3*pi)', // the e⁰ term forgotten
      'p-phi': '(3/e^(3*pi))/2 * exp(3*phi/2)', // k/(m + 1) e^(aφ) with that k
      'p-theta': 'cos(theta)*sin(theta)', // the factor m + 1 lost
      'cdf-theta': 'sin(theta)^2/2', // ∫₀^θ of that
      'cdf-phi': '1 - cos(phi)', // unrelated to anything
      'theta-of-xi': 'asin(sqrt(2*xi))', // the inverse of sin²θ/2 (on ξ ≤ 1/2 only: not finite beyond)
    };
    const out = await gradeAnswers(v, texts);
    expect(out.k.value).toBe('mistake:forgot-e0');
    expect(out['p-phi'].value).toBe('consistent');
    expect(out['p-phi'].message).toContain('Consistent with your k, which was wrong');
    expect(out['p-theta'].value).toBe('incorrect');
    expect(out['cdf-theta'].value).toBe('consistent');
    expect(out['cdf-theta'].message).toContain('p(θ)');
    expect(out['cdf-phi'].value).toBe('incorrect');
    expect(out['theta-of-xi'].value).toBe('incorrect');
  });
  it('an inversion consistent with a wrong CDF beats the named mistake it also is', async () => {
    const out = await gradeAnswers(v, { 'cdf-theta': '1 - cos(theta)', 'theta-of-xi': 'acos(1 - xi)' });
    expect(out['cdf-theta'].value).toBe('incorrect');
    expect(out['theta-of-xi'].value).toBe('consistent');
    // with the right CDF the same inversion is the named mistake, not follow-through
    const right = await gradeAnswers(v, { 'cdf-theta': '1 - cos(theta)^2', 'theta-of-xi': 'acos(1 - xi)' });
    expect(right['theta-of-xi'].value).toBe('mistake:missing-root');
  });
  it('follow-through earns half marks (less the attempt penalty)', async () => {
    const texts = { 'p-theta': 'cos(theta)*sin(theta)', 'cdf-theta': 'sin(theta)^2/2' };
    const s = applyCheck(v, newSession(v), texts, await gradeAnswers(v, texts));
    expect(s.answers['cdf-theta'].best).toBe(SCORING.followCredit);
    expect(s.answers['p-theta'].best).toBe(0);
  });
});

describe('Q4(c) from the student’s own normalization', () => {
  it('importance = their wrong I is consistent', async () => {
    const seed = [...Array(200).keys()].find((s) => q4Params(s).a !== 0)!;
    const v = q4Variant(seed);
    const P = q4Params(seed);
    const Fb = q4Functions(P).F(P.b); // F(a) not subtracted
    const out = await gradeAnswers(v, { exact: String(Fb), importance: String(Fb) });
    expect(out.exact.value).toBe('mistake:no-lower-limit');
    expect(out.importance.value).toBe('consistent');
    const ok = await gradeAnswers(v, { exact: String(num(v, 'exact')), importance: String(Fb) });
    expect(ok.importance.value).not.toBe('consistent');
  });
});

describe('Q5: roots and case from the student’s own a, b, c', () => {
  it('a sign slip in b carries into the roots, the hit and the case', async () => {
    let seed = 0;
    let v = q5Variant(seed);
    while (allAnswers(v).find((a) => a.name === 'case')!.kind !== 'choice' || !(num(v, 't0')! > 0))
      v = q5Variant(++seed);
    const [a, b, c] = [num(v, 'a')!, num(v, 'b')!, num(v, 'c')!];
    const D = b * b - 4 * a * c; // the same with −b
    const r0 = (b - Math.sqrt(D)) / (2 * a);
    const r1 = (b + Math.sqrt(D)) / (2 * a);
    const out = await gradeAnswers(v, {
      a: String(a),
      b: String(-b),
      c: String(c),
      discriminant: String(D),
      t0: String(r0),
      t1: String(r1),
      't-hit': r0 >= 0 ? String(r0) : r1 >= 0 ? String(r1) : 'none',
      case: r0 >= 0 ? 'two-hits' : r1 >= 0 ? 'inside' : 'behind',
    });
    expect(out.b.value).toBe('mistake:b-sign');
    expect(out.discriminant.value).toBe('correct');
    expect(out.t0.value).toBe('consistent');
    expect(out.t0.message).toContain('your b');
    expect(out.t1.value).toBe('consistent');
    expect(out['t-hit'].value).toBe('consistent');
    expect(out.case.value).toBe('consistent');
  });
  it('a wrong c carries into Δ', async () => {
    const v = q5Variant(3);
    const [a, b, c] = [num(v, 'a')!, num(v, 'b')!, num(v, 'c')! + 5];
    const out = await gradeAnswers(v, {
      a: String(a),
      b: String(b),
      c: String(c),
      discriminant: String(b * b - 4 * a * c),
    });
    expect(out.c.value).not.toBe('correct');
    expect(out.discriminant.value).toBe('consistent');
  });
});

describe('Q6: dω from the own r and cos θ_l; the estimate from the own dω', () => {
  it('no cos θ_l in dω, and none in the estimate: consistent', async () => {
    const v = q6Variant(3);
    const dwSpec = allAnswers(v).find((a) => a.name === 'd-omega') as NumberAnswer;
    const estSpec = allAnswers(v).find((a) => a.name === 'estimate') as NumberAnswer;
    const noCos = dwSpec.mistakes.find((m) => m.id === 'no-cos')!.value;
    const noCosL = estSpec.mistakes.find((m) => m.id === 'no-cos-l')!.value;
    const out = await gradeAnswers(v, { 'd-omega': String(noCos), estimate: String(noCosL) });
    expect(out['d-omega'].value).toBe('mistake:no-cos');
    expect(out.estimate.value).toBe('consistent');
    const alone = await gradeAnswers(v, { estimate: String(noCosL) });
    expect(alone.estimate.value).toBe('mistake:no-cos-l');
    const r = num(v, 'r')! * 1.1;
    const cos = num(v, 'cos-theta-l')!;
    const dA = Number(g(v, 'psize')) ** 2;
    const chain = await gradeAnswers(v, {
      r: String(r),
      'cos-theta-l': String(cos),
      'd-omega': String((dA * cos) / (r * r)),
    });
    expect(chain['d-omega'].value).toBe('consistent');
  });
});

describe('Q3: the sphere lookup at the student’s own (u, v)', () => {
  it('u not normalized, then the lookup there: consistent', async () => {
    const v = q3Variant(5);
    const [x, y, z] = ['x', 'y', 'z'].map((n) => Number(g(v, n)));
    const sp = sphericalUV(x, y, z);
    if (!sp.ok) throw new Error('unreachable');
    const grid = parseGrid(g(v, 'grid'));
    if (!grid.ok) throw new Error(grid.message);
    const look = bilinear(grid.grid, sp.phi, sp.v, EXAM_LOOKUP);
    const out = await gradeAnswers(v, {
      'sphere-u': String(sp.phi),
      'sphere-v': String(sp.v),
      'sphere-bilinear': String(look),
    });
    expect(out['sphere-u'].value).toBe('mistake:no-normalization');
    if (Math.abs(look - num(v, 'sphere-bilinear')!) > 1e-6)
      expect(out['sphere-bilinear'].value).toBe('consistent');
  });
});
