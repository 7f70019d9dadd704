import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { formatNumber, readoutText, readoutValue, writeReadout } from '../../src/ui/Readout';

describe('readoutValue (the contract’s data-value)', () => {
  it('is String(x) for finite numbers and "none" otherwise', () => {
    expect(readoutValue(17.8)).toBe('17.8');
    expect(readoutValue(56 / 3)).toBe(String(56 / 3));
    expect(readoutValue(NaN)).toBe('none');
    expect(readoutValue(Infinity)).toBe('none');
    expect(readoutValue(null)).toBe('none');
    expect(readoutValue(undefined)).toBe('none');
    expect(readoutValue('two-hits')).toBe('two-hits');
  });
  it('round-trips every finite double exactly (property)', () => {
    fc.assert(
      fc.property(
        fc.double({ noNaN: true, noDefaultInfinity: true }),
        (x) => Object.is(Number(readoutValue(x)), x) || (x === 0 && Number(readoutValue(x)) === 0),
      ),
    );
  });
});

describe('formatNumber (visible text)', () => {
  it('rounds to the requested significant digits and trims zeros', () => {
    expect(formatNumber(56 / 3, 6)).toBe('18.6667');
    expect(formatNumber(17.8, 6)).toBe('17.8');
    expect(formatNumber(2, 6)).toBe('2');
    expect(formatNumber(0)).toBe('0');
    expect(formatNumber(-0.000123456, 3)).toBe('-0.000123');
  });
  it('uses ×10ⁿ for very small and very large magnitudes', () => {
    expect(formatNumber(1.5e-12, 3)).toBe('1.5×10⁻¹²');
    expect(formatNumber(6.02e23, 3)).toBe('6.02×10²³');
  });
  it('never leaks JavaScript’s e-notation, even when the integer part exceeds the digits', () => {
    expect(formatNumber(-2e8, 6)).toBe('-2×10⁸');
    expect(formatNumber(1234567, 3)).toBe('1.23×10⁶');
    expect(formatNumber(123456, 6)).toBe('123456');
    fc.assert(
      fc.property(
        fc.double({ noNaN: true, noDefaultInfinity: true }),
        fc.integer({ min: 1, max: 17 }),
        (x, d) => !/e/.test(formatNumber(x, d)),
      ),
    );
  });
  it('never shows a non-finite number', () => {
    expect(formatNumber(NaN)).toBe('—');
    expect(formatNumber(-Infinity)).toBe('—');
  });
});

describe('writeReadout (a LiveReadout written without React)', () => {
  /** A minimal element: attributes, title, text. */
  function fakeOutput() {
    const attrs = new Map<string, string>();
    let writes = 0;
    const el = {
      title: '',
      textContent: '' as string | null,
      get firstChild() {
        return el.textContent ? {} : null;
      },
      getAttribute: (k: string) => attrs.get(k) ?? null,
      setAttribute: (k: string, v: string) => {
        writes++;
        attrs.set(k, v);
      },
      writes: () => writes,
    };
    return el;
  }
  it('writes what Readout renders: data-value, title and the rounded text; nothing when unchanged', () => {
    const el = fakeOutput();
    writeReadout(el as unknown as HTMLElement, 56 / 3, 6);
    expect(el.getAttribute('data-value')).toBe(String(56 / 3));
    expect(el.title).toBe(String(56 / 3));
    expect(el.textContent).toBe('18.6667');
    const n = el.writes();
    writeReadout(el as unknown as HTMLElement, 56 / 3, 6);
    expect(el.writes()).toBe(n);
    writeReadout(el as unknown as HTMLElement, null);
    expect(el.getAttribute('data-value')).toBe('none');
    expect(el.title).toBe('not applicable');
    expect(el.textContent).toBe('—');
    writeReadout(el as unknown as HTMLElement, 'two-hits');
    expect(el.textContent).toBe('two-hits');
    expect(readoutText(1.5e-12, 3)).toBe('1.5×10⁻¹²');
  });
});
