import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { formatFixed } from '../../src/core/format';

describe('formatFixed', () => {
  it('writes a fixed number of decimals, and never a negative zero', () => {
    expect(formatFixed(1.25, 1)).toBe('1.3');
    expect(formatFixed(-3.14159, 2)).toBe('-3.14');
    expect(formatFixed(-0.04, 1)).toBe('0.0');
    expect(formatFixed(-0, 0)).toBe('0');
    expect(formatFixed(-0.4, 0)).toBe('0');
    expect(formatFixed(-0.6, 0)).toBe('-1');
  });
  it('reads back within half a unit of the last decimal (property)', () => {
    fc.assert(
      fc.property(fc.double({ min: -1e6, max: 1e6, noNaN: true }), fc.integer({ min: 0, max: 6 }), (x, d) => {
        const s = formatFixed(x, d);
        expect(s.startsWith('-0') && /^-0(\.0*)?$/.test(s)).toBe(false);
        expect(Math.abs(Number(s) - x)).toBeLessThanOrEqual(0.5 * 10 ** -d + 1e-9);
      }),
    );
  });
});
