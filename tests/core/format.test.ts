import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { formatRounded } from '../../src/core/format';

describe('formatRounded', () => {
  it('rounds to the given significant digits and trims trailing zeros', () => {
    expect(formatRounded(17.8)).toBe('17.8');
    expect(formatRounded(0.123456)).toBe('0.1235');
    expect(formatRounded(2 / 3, 6)).toBe('0.666667');
    expect(formatRounded(0.4000000000000001)).toBe('0.4');
    expect(formatRounded(-1.5)).toBe('-1.5');
  });

  it('writes large and small numbers without an exponent where JavaScript does', () => {
    expect(formatRounded(12345)).toBe('12350');
    expect(formatRounded(0.0000123456)).toBe('0.00001235');
    expect(formatRounded(1.23456e-7)).toBe('1.235e-7');
  });

  it('writes −0 as 0 and a non-finite value as a dash', () => {
    expect(formatRounded(-0)).toBe('0');
    expect(formatRounded(Number.NaN)).toBe('—');
    expect(formatRounded(-Infinity)).toBe('—');
  });

  it('reads back as the number rounded to its digits', () => {
    fc.assert(
      fc.property(
        fc.double({ noNaN: true, noDefaultInfinity: true }),
        fc.integer({ min: 1, max: 12 }),
        (x, d) => {
          expect(Number(formatRounded(x, d))).toBe(Number(x.toPrecision(d)) + 0);
        },
      ),
      { seed: 7 },
    );
  });
});
