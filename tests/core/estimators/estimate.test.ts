import { describe, expect, it } from 'vitest';
import {
  estimateFromTerms,
  importanceEstimate,
  importanceTermsInto,
  uniformEstimate,
} from '../../../src/core/estimators/estimate';
import { Rng } from '../../../src/core/random';

const f = (x: number) => (x + 2) * (x + 2);
const EXAM_X = [1.16, 1.98, 0.54, 1.26];

describe('uniform estimator', () => {
  it('reproduces the exam Q4(b) arithmetic from the formula', () => {
    const fx = Float64Array.from(EXAM_X, f);
    const r = uniformEstimate(fx, 0, 2);
    const byHand = ((1.16 + 2) ** 2 + (1.98 + 2) ** 2 + (0.54 + 2) ** 2 + (1.26 + 2) ** 2) / 4 / 0.5;
    expect(r.estimate).toBeCloseTo(byHand, 13);
    expect(r.n).toBe(4);
    expect(r.invalid).toBe(0);
    // per-term values 2 f(x); standard error from the unbiased sample variance
    const terms = EXAM_X.map((x) => 2 * f(x));
    const m = terms.reduce((s, t) => s + t, 0) / 4;
    const s2 = terms.reduce((s, t) => s + (t - m) ** 2, 0) / 3;
    expect(r.stderr).toBeCloseTo(Math.sqrt(s2 / 4), 12);
  });

  it('is within 4σ of 56/3 with 1e5 random samples', () => {
    const rng = new Rng(11);
    const fx = new Float64Array(100000);
    for (let i = 0; i < fx.length; i++) fx[i] = f(2 * rng.nextFloat());
    const r = uniformEstimate(fx, 0, 2);
    expect(Math.abs(r.estimate - 56 / 3)).toBeLessThan(4 * r.stderr);
    // true per-term variance of 2 f(U·2): E[(2f)²] − I², with E over U[0,2]
    const e2 = (4 / 2) * ((4 ** 5 - 2 ** 5) / 5); // ∫₀² 4 f² dx / 2 = 2 ∫ (x+2)^4 dx
    const trueVar = e2 - (56 / 3) ** 2;
    expect(Math.abs(r.variance - trueVar) / trueVar).toBeLessThan(0.03);
  });

  it('counts non-finite f values as invalid', () => {
    const r = uniformEstimate([1, NaN, Infinity, 3], 0, 1);
    expect(r.invalid).toBe(2);
    expect(r.estimate).toBe(2);
  });
});

describe('importance estimator', () => {
  it('p ∝ f gives exactly the integral at every sample (zero variance)', () => {
    const fx = Float64Array.from(EXAM_X, f);
    const px = Float64Array.from(EXAM_X, (x) => (3 / 56) * f(x));
    const r = importanceEstimate(fx, px);
    expect(r.estimate).toBeCloseTo(56 / 3, 13);
    expect(r.variance).toBeLessThan(1e-26);
  });

  it('f = 0 terms are 0 whatever p is; p = 0 with f ≠ 0 is invalid', () => {
    const out = new Float64Array(4);
    const bad = importanceTermsInto([0, 2, 3, 0], [0, 0, 1.5, NaN], out);
    expect(bad).toBe(1);
    expect(out[0]).toBe(0);
    expect(Number.isNaN(out[1])).toBe(true);
    expect(out[2]).toBe(2);
    expect(out[3]).toBe(0);
    const r = importanceEstimate([0, 2, 3, 0], [0, 0, 1.5, NaN]);
    expect(r.invalid).toBe(1);
    expect(r.n).toBe(3);
    expect(r.estimate).toBeCloseTo(2 / 3, 15);
    const t = estimateFromTerms(out);
    expect(t.invalid).toBe(1);
    expect(t.estimate).toBeCloseTo(2 / 3, 15);
  });

  it('empty input gives NaN estimate, not a number', () => {
    expect(Number.isNaN(importanceEstimate([], []).estimate)).toBe(true);
  });
});
