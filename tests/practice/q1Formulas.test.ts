/**
 * Q1's formula answers as a student types them: the classic slips (the inverted Jacobian, the lost
 * lower limit, the lost 1/a, the lost ½) are each named, and equivalent forms of the right answers
 * (another trigonometric form, the inverse by arcsine, the inverse that maps ξ to 1 − ξ) are correct,
 * the last with a note that it gives the same distribution.
 */
import { describe, expect, it } from 'vitest';
import { q1Params } from '../../src/practice/q1Density';
import { q1Variant } from '../../src/practice/q1';
import { gradeAnswers } from '../../src/practice/session';

/** The first seed whose lobe has m = 1 and a ≠ 1, where every slip gives a different formula. */
function seedWithDistinctSlips(): number {
  let seed = 0;
  while (!(q1Params(seed).m === 1 && q1Params(seed).a.p !== q1Params(seed).a.q)) seed++;
  return seed;
}

describe('Q1 formulas', () => {
  const seed = seedWithDistinctSlips();
  const P = q1Params(seed);
  const a = `(${P.a.p}/${P.a.q})`;
  const E = `(e^(2*pi*${a}) - 1)`;
  const v = q1Variant(seed);

  it('each classic slip is named by its id', async () => {
    const out = await gradeAnswers(v, {
      'p-theta': '2*cos(θ)/sin(θ)',
      'p-phi': `exp(${a}*phi)/${E}`,
      'cdf-theta': '-cos(theta)^2',
      'cdf-phi': `exp(${a}*phi)/${E}`,
      'theta-of-xi': 'acos(1 - 2*xi)',
      'phi-of-xi': `ln(1 + ${E}*ξ₂)`,
    });
    expect(out['p-theta'].value).toBe('mistake:inverted-jacobian');
    expect(out['p-phi'].value).toBe('mistake:missing-1-over-a');
    expect(out['cdf-theta'].value).toBe('mistake:no-lower-limit');
    expect(out['cdf-phi'].value).toBe('mistake:no-lower-limit');
    expect(out['theta-of-xi'].value).toBe('mistake:missing-half');
    expect(out['phi-of-xi'].value).toBe('mistake:missing-1-over-a');
    for (const verdict of Object.values(out)) expect(verdict.message).toMatch(/\w{4,}/);
  });

  it('equivalent forms of the right answers are correct; ξ ↦ 1 − ξ is said to give the same distribution', async () => {
    const out = await gradeAnswers(v, {
      'p-theta': '2*sin(theta)*cos(theta)',
      'cdf-theta': 'sin(theta)^2',
      'theta-of-xi': 'asin(sqrt(ξ))',
      'phi-of-xi': `log(1 + ${E}*(1 - xi))/${a}`,
    });
    for (const n of ['p-theta', 'cdf-theta', 'theta-of-xi', 'phi-of-xi'])
      expect(out[n].value, n).toBe('correct');
    expect(out['phi-of-xi'].message).toContain('same distribution');
  });
});
