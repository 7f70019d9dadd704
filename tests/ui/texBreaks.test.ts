import { describe, expect, it } from 'vitest';
import { keepParenthesesTogether as keep, keepTextParenthesesTogether } from '../../src/ui/texBreaks';

describe('keepParenthesesTogether', () => {
  it('makes each top-level parenthesized group with an operator one atom', () => {
    expect(keep('I = \\int_0^2 (x + 2)^2 \\, dx')).toBe('I = \\int_0^2 {(x + 2)}^2 \\, dx');
    expect(keep('\\phi = \\ln((e^{2\\pi} - 1)\\xi_2 + 1)')).toBe('\\phi = \\ln{((e^{2\\pi} - 1)\\xi_2 + 1)}');
    expect(keep('P(\\theta) = (1 - \\cos 2\\theta)/2')).toBe('P(\\theta) = {(1 - \\cos 2\\theta)}/2');
    expect(keep('a (b \\cdot c) + (d \\le e)')).toBe('a {(b \\cdot c)} + {(d \\le e)}');
  });

  it('leaves alone what cannot break or cannot be grouped', () => {
    for (const tex of [
      'f(x) = p(\\omega)', // no operator inside the parentheses
      '\\left( x + 1 \\right) = \\bigl(y - 2\\bigr)', // sized delimiters
      '\\frac{1}{(x + 2)} + \\text{(a + b)}', // inside braces: already one atom
      '\\begin{aligned} (a &= b + c) \\\\ d &= e \\end{aligned}', // an alignment inside
      '[0, 2\\pi) \\cup (0 + 1', // unbalanced
      '\\( x \\) + 1', // control symbols
      '(x \\inf y)', // \\inf is not \\in
    ])
      expect(keep(tex), tex).toBe(tex);
  });
});

describe('keepTextParenthesesTogether', () => {
  it('turns the spaces inside a formula’s parentheses into no-break spaces', () => {
    const nb = '\u00a0';
    expect(keepTextParenthesesTogether('p(x) = 3(x + 2)²/56')).toBe(`p(x) = 3(x${nb}+${nb}2)²/56`);
    expect(keepTextParenthesesTogether('the robust form 4a(r² − |ℓ|²), which')).toBe(
      `the robust form 4a(r²${nb}−${nb}|ℓ|²), which`,
    );
    expect(keepTextParenthesesTogether('atan2(√(x² + y²), z)')).toBe(`atan2(√(x²${nb}+${nb}y²),${nb}z)`);
  });

  it('leaves prose in parentheses alone', () => {
    for (const t of [
      'a point (the exam’s) here',
      'five terms (i, j) and (the well-known one)',
      'x (a',
      'the sphere (Δ = 0: it touches it, a double root)',
    ])
      expect(keepTextParenthesesTogether(t)).toBe(t);
  });
});
