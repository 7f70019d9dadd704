/** Q5: the constant term c without its − r² is named, and the centre is C, never the constant c. */
import { describe, expect, it } from 'vitest';
import { checkAnswer } from '../../src/practice/check';
import { allAnswers, type NumberAnswer } from '../../src/practice/model';
import { q5Params, q5Variant } from '../../src/practice/q5';

describe('Q5 constant term', () => {
  it('c = |o − C|² (the − r² forgotten) is the named mistake on every sampled seed', async () => {
    for (let seed = 0; seed < 60; seed++) {
      const P = q5Params(seed);
      const v = q5Variant(seed);
      const f = P.o.map((x, i) => x - P.c[i]);
      const ff = f[0] ** 2 + f[1] ** 2 + f[2] ** 2;
      const c = allAnswers(v).find((a) => a.name === 'c') as NumberAnswer;
      const r = await checkAnswer(c, String(ff));
      expect(r.value, `seed ${seed}`).toBe('mistake:forgot-r-squared');
      expect(r.message).toContain('r²');
    }
  });

  it('writes the centre as C: no “centre c”, no o − c, in the statement, givens, hints and steps', () => {
    for (let seed = 0; seed < 30; seed++) {
      const v = q5Variant(seed);
      const texts = [
        v.statement,
        ...v.givens.map((g) => g.label),
        ...v.parts.flatMap((p) => [...p.hint, ...p.steps]).flatMap((s) => [s.text ?? '', s.tex ?? '']),
        ...allAnswers(v).flatMap((a) => ('mistakes' in a ? a.mistakes.map((m) => m.message) : [])),
      ];
      for (const t of texts)
        expect(t, `seed ${seed}`).not.toMatch(/centre c\b|[o(] ?[-−] ?c\b|\bc ?[-−] ?o\b/);
      expect(v.statement).toMatch(/centre C = /);
    }
  });
});
