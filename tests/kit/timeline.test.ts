import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { advance, clampPosition, openingPosition, timelineParams } from '../../src/kit/timeline';
import { parseParams, serializeParams } from '../../src/kit/params';

describe('timeline advance', () => {
  it('moves max/duration position units per second at 1×, scaled by speed', () => {
    expect(advance(0, 500, { max: 1, duration: 2, speed: 1, loop: false })).toEqual({
      t: 0.25,
      ended: false,
    });
    expect(advance(0, 500, { max: 64, duration: 4, speed: 4, loop: false }).t).toBeCloseTo(32, 12);
    expect(advance(0, 500, { max: 64, duration: 4, speed: 0.25, loop: false }).t).toBeCloseTo(2, 12);
  });
  it('stops at the end without loop and wraps with loop', () => {
    expect(advance(0.9, 1000, { max: 1, duration: 1, speed: 1, loop: false })).toEqual({ t: 1, ended: true });
    const w = advance(0.9, 200, { max: 1, duration: 1, speed: 1, loop: true });
    expect(w.ended).toBe(false);
    expect(w.t).toBeCloseTo(0.1, 12);
  });
  it('never leaves [0, max] for any finite input', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 100, noNaN: true }),
        fc.double({ min: 0, max: 1e4, noNaN: true }),
        fc.double({ min: 0.01, max: 1000, noNaN: true }),
        fc.boolean(),
        (t0, dt, max, loop) => {
          const t = Math.min(t0, max);
          const r = advance(t, dt, { max, duration: 3, speed: 2, loop });
          return r.t >= 0 && r.t <= max;
        },
      ),
    );
  });
});

describe('clampPosition', () => {
  it('clamps, rounds integer timelines and maps NaN to 0', () => {
    expect(clampPosition(-1, 1, false)).toBe(0);
    expect(clampPosition(2, 1, false)).toBe(1);
    expect(clampPosition(3.6, 10, true)).toBe(4);
    expect(clampPosition(Number.NaN, 10, true)).toBe(0);
  });
});

describe('timelineParams', () => {
  it('round-trips t and play through the URL parser and clamps t to the timeline', () => {
    const schema = { ...timelineParams({ max: 1 }) };
    const v = parseParams(schema, 't=0.375&play=1').values;
    expect(v).toEqual({ t: 0.375, play: true });
    expect(parseParams(schema, serializeParams(schema, v, {})).values).toEqual(v);
    const bad = parseParams(schema, 't=7');
    expect(bad.values.t).toBe(1);
    expect(bad.problems.map((p) => p.name)).toContain('t');
  });
});

describe('openingPosition', () => {
  it('opens where the link says, except that play=1 at the end plays from the start', () => {
    expect(openingPosition(0.3, 1, false, true)).toBe(0.3);
    expect(openingPosition(1, 1, false, true)).toBe(0);
    expect(openingPosition(1, 1, false, false)).toBe(1);
    expect(openingPosition(5000, 1024, true, true)).toBe(0);
    expect(openingPosition(NaN, 1024, true, true)).toBe(0);
    fc.assert(
      fc.property(
        fc.double(),
        fc.double({ min: 0.01, max: 1e4, noNaN: true }),
        fc.boolean(),
        (t, max, integer) => {
          const o = openingPosition(t, max, integer, true);
          return o >= 0 && o < max;
        },
      ),
    );
  });
});
