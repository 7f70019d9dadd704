import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { compileExpression, MAX_EXPRESSION_LENGTH } from '../../../src/core/expr';

// Pieces that make plausible (and implausible) user input.
const TOKENS = [
  'theta',
  'phi',
  'x',
  'y',
  'θ',
  'φ',
  'pi',
  'e',
  'tau',
  '1',
  '2.5',
  '1e3',
  '0x1f',
  '+',
  '-',
  '*',
  '/',
  '^',
  '(',
  ')',
  ',',
  '.',
  'sin(',
  'cos(',
  'exp(',
  'log(',
  'sqrt(',
  'min(',
  'atan2(',
  'foo(',
  'import(',
  'evaluate(',
  '=',
  ':',
  '?',
  '[',
  ']',
  '{',
  '}',
  '"',
  "'",
  ';',
  '!',
  '<',
  '%',
  ' ',
  '\n',
  'mod',
  'and',
  'true',
  'Infinity',
  'NaN',
  'cm',
  '@',
  '#',
  '$',
];

describe('compileExpression never throws and only compiles safe expressions (fuzz)', () => {
  it('random token strings resolve to { ok } results; compiled ones evaluate to numbers', async () => {
    await fc.assert(
      fc.asyncProperty(fc.array(fc.constantFrom(...TOKENS), { maxLength: 40 }), async (parts) => {
        const src = parts.join('');
        const r = await compileExpression(src, ['theta', 'phi']);
        if (!r.ok) return typeof r.message === 'string' && r.message.length > 0;
        const v = r.fn(0.3, 1.7);
        return typeof v === 'number' && typeof r.tex === 'string' && typeof r.text === 'string';
      }),
      { numRuns: 400 },
    );
  });

  it('arbitrary Unicode strings resolve without throwing', async () => {
    await fc.assert(
      fc.asyncProperty(fc.string({ unit: 'grapheme', maxLength: 80 }), async (src) => {
        const r = await compileExpression(src, ['x']);
        return r.ok ? typeof r.fn(1) === 'number' : r.message.length > 0;
      }),
      { numRuns: 300 },
    );
  });

  it('rejects non-string input and over-long input without parsing', async () => {
    expect((await compileExpression(undefined as unknown as string, ['x'])).ok).toBe(false);
    const long = 'x+'.repeat(MAX_EXPRESSION_LENGTH) + 'x';
    const r = await compileExpression(long, ['x']);
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.message).toMatch(/too long/);
  });
});
