// The 3D view's buffer capacity: a power of two of at least 4096 that holds n points, and never
// more than MAX_N, so that n = MAX_N fits exactly without a larger allocation.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { capacityFor } from '../../../src/scenes/hemisphere/view/pointBuffers';
import { MAX_N } from '../../../src/scenes/hemisphere/params';

describe('capacityFor', () => {
  it('holds n points in the smallest power of two ≥ 4096, capped at MAX_N', () => {
    fc.assert(
      fc.property(fc.integer({ min: 0, max: MAX_N }), (n) => {
        const c = capacityFor(n);
        expect(c).toBeGreaterThanOrEqual(n);
        expect(c).toBeLessThanOrEqual(MAX_N);
        if (c < MAX_N) {
          expect(Number.isInteger(Math.log2(c))).toBe(true);
          expect(c).toBeGreaterThanOrEqual(4096);
          // the smallest such: half of it would not hold n (or would go under 4096)
          expect(c === 4096 || c / 2 < n).toBe(true);
        } else {
          // capped: the largest power of two below MAX_N would not hold n
          expect(n).toBeGreaterThan(2 ** Math.floor(Math.log2(MAX_N - 1)));
        }
      }),
      { seed: 7, numRuns: 500 },
    );
  });

  it('at the edges: 4096 for a few points, MAX_N for MAX_N and for its neighbour below', () => {
    expect(capacityFor(1)).toBe(4096);
    expect(capacityFor(4097)).toBe(8192);
    expect(capacityFor(MAX_N)).toBe(MAX_N);
    expect(capacityFor(MAX_N - 1)).toBe(MAX_N);
    expect(capacityFor(200_000)).toBe(262_144);
  });
});
