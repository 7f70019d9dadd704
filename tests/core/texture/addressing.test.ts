import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { addressCoord, addressIndex, WRAP_MODES, type WrapMode } from '../../../src/core/texture';

describe('addressCoord', () => {
  it('leaves every coordinate in [0, 1] unchanged, including exactly 0 and 1, in every mode', () => {
    for (const mode of WRAP_MODES) {
      for (const t of [0, Number.MIN_VALUE, 2 ** -53, 0.25, 0.5, 1 - 2 ** -53, 1]) {
        expect(addressCoord(t, mode)).toBe(t);
      }
    }
  });

  it('handles hand-picked outside coordinates (table from the definitions)', () => {
    const cases: [WrapMode, number, number][] = [
      ['clamp', -0.25, 0],
      ['clamp', -1e300, 0],
      ['clamp', 1.25, 1],
      ['clamp', 7, 1],
      ['repeat', 1.25, 0.25],
      ['repeat', -0.25, 0.75],
      ['repeat', 2, 0],
      ['repeat', -1, 0],
      ['repeat', 3.5, 0.5],
      ['mirror', 1.25, 0.75],
      ['mirror', -0.25, 0.25],
      ['mirror', 2, 0],
      ['mirror', -1, 1],
      ['mirror', 3.5, 0.5],
      ['mirror', 2.75, 0.75],
    ];
    for (const [mode, t, want] of cases) expect(addressCoord(t, mode), `${mode} ${t}`).toBeCloseTo(want, 14);
  });

  it('never returns 1 from repeat for a tiny negative coordinate (t − ⌊t⌋ rounds to 1)', () => {
    expect(1 + -1e-17).toBe(1); // the rounding this guards against
    expect(addressCoord(-1e-17, 'repeat')).toBe(0);
    expect(addressCoord(-1e-17, 'mirror')).toBeCloseTo(0, 15);
  });

  it('maps non-finite input to 0 (safe fallback)', () => {
    for (const mode of WRAP_MODES) {
      expect(addressCoord(NaN, mode)).toBe(0);
      expect(addressCoord(Infinity, mode)).toBe(0);
    }
  });

  it('always lands in [0, 1]; repeat has period 1, mirror is even with period 2 (property)', () => {
    fc.assert(
      fc.property(fc.double({ min: -1e6, max: 1e6, noNaN: true }), (t) => {
        for (const mode of WRAP_MODES) {
          const a = addressCoord(t, mode);
          if (!(a >= 0 && a <= 1)) return false;
        }
        if (t < 0 || t > 1) {
          const frac = t - Math.floor(t);
          if (Math.abs(addressCoord(t, 'repeat') - (frac >= 1 ? 0 : frac)) > 0) return false;
        }
        // evenness of mirror (up to the rounding of the reduction)
        if (Math.abs(addressCoord(-t, 'mirror') - addressCoord(t, 'mirror')) > 1e-9) return false;
        if (Math.abs(addressCoord(t + 2, 'mirror') - addressCoord(t, 'mirror')) > 1e-9) return false;
        return true;
      }),
    );
  });

  it('mirror is continuous (|Δ output| ≤ |Δ input|)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -50, max: 50, noNaN: true }),
        fc.double({ min: 0, max: 0.01, noNaN: true }),
        (t, d) => {
          return Math.abs(addressCoord(t + d, 'mirror') - addressCoord(t, 'mirror')) <= d + 1e-12;
        },
      ),
    );
  });
});

describe('addressIndex (OpenGL CLAMP_TO_EDGE, REPEAT, MIRRORED_REPEAT)', () => {
  it('matches a hand table for n = 4', () => {
    const i = [-5, -4, -1, 0, 3, 4, 5, 7, 8, 9];
    expect(i.map((k) => addressIndex(k, 4, 'clamp'))).toEqual([0, 0, 0, 0, 3, 3, 3, 3, 3, 3]);
    expect(i.map((k) => addressIndex(k, 4, 'repeat'))).toEqual([3, 0, 3, 0, 3, 0, 1, 3, 0, 1]);
    // mirrored sequence …, 3 2 1 0 | 0 1 2 3 | 3 2 1 0 | 0 1 …
    expect(i.map((k) => addressIndex(k, 4, 'mirror'))).toEqual([3, 3, 0, 0, 3, 3, 2, 0, 0, 1]);
  });

  it('lands in 0 … n − 1 and is the identity inside (property)', () => {
    fc.assert(
      fc.property(fc.integer({ min: -100000, max: 100000 }), fc.integer({ min: 1, max: 64 }), (k, n) => {
        for (const mode of WRAP_MODES) {
          const a = addressIndex(k, n, mode);
          if (!(Number.isInteger(a) && a >= 0 && a < n)) return false;
          if (k >= 0 && k < n && a !== k) return false;
        }
        // repeat: same residue; mirror: symmetric about −½ (i and −1 − i agree)
        if ((((addressIndex(k, n, 'repeat') - k) % n) + n) % n !== 0) return false;
        return addressIndex(k, n, 'mirror') === addressIndex(-1 - k, n, 'mirror');
      }),
    );
  });
});
