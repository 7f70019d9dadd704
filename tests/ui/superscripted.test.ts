import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { caretParts, type CaretPart } from '../../src/ui/Superscripted';

/** The parts written back with ^( ) around every power: the text with its carets made explicit. */
function flat(parts: CaretPart[]): string {
  return parts.map((p) => (typeof p === 'string' ? p : `^(${flat(p.sup)})`)).join('');
}

describe('caretParts', () => {
  it('sets parenthesised, braced and bare powers', () => {
    expect(caretParts('e^(2πa) − 1')).toEqual(['e', { sup: ['2πa'] }, ' − 1']);
    expect(caretParts('cos^3 θ')).toEqual(['cos', { sup: ['3'] }, ' θ']);
    expect(caretParts('e^φ, then')).toEqual(['e', { sup: ['φ'] }, ', then']);
    expect(caretParts('x^{n+1}')).toEqual(['x', { sup: ['n+1'] }]);
    expect(caretParts('(1 − ξ₁)^(1/(m+1))')).toEqual(['(1 − ξ₁)', { sup: ['1/(m+1)'] }]);
  });
  it('nests powers of powers', () => {
    expect(caretParts('e^(x^2)')).toEqual(['e', { sup: ['x', { sup: ['2'] }] }]);
  });
  it('leaves a caret it cannot read as text', () => {
    expect(caretParts('a ^ b')).toEqual(['a ^ b']);
    expect(caretParts('e^(unclosed')).toEqual(['e^(unclosed']);
    expect(caretParts('end^')).toEqual(['end^']);
  });
  it('text without carets is one part, unchanged; no text is lost', () => {
    fc.assert(
      fc.property(fc.string(), (s) => {
        const parts = caretParts(s);
        if (!s.includes('^')) expect(parts).toEqual(s ? [s] : []);
        // every character but the carets and the group marks that were read survives, in order
        const kept = flat(parts).replace(/\^\(|[(){}^]/g, '');
        expect(kept).toBe(s.replace(/[(){}^]/g, ''));
      }),
    );
  });
});
