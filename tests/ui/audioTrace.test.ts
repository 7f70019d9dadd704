import { describe, expect, it } from 'vitest';
import { pointText } from '../../src/ui/audioTrace';
import { PITCH_HI, PITCH_LO, panOf, pitchOf, rangeOf } from '../../src/ui/audioEngine';

const fmt = (v: number) =>
  Number.isFinite(v) ? String(Math.round(v * 100) / 100).replace('-', '−') : 'no value';

describe('audio trace', () => {
  it('pitch follows y on a log scale between two octaves; pan follows x', () => {
    expect(pitchOf(0, 0, 1)).toBeCloseTo(PITCH_LO, 9);
    expect(pitchOf(1, 0, 1)).toBeCloseTo(PITCH_HI, 9);
    expect(pitchOf(0.5, 0, 1)).toBeCloseTo(Math.sqrt(PITCH_LO * PITCH_HI), 9);
    expect(pitchOf(5, 0, 1)).toBe(PITCH_HI);
    expect(pitchOf(3, 3, 3)).toBeGreaterThan(PITCH_LO);
    expect(panOf(0, 0, 10)).toBe(-1);
    expect(panOf(5, 0, 10)).toBe(0);
    expect(panOf(10, 0, 10)).toBe(1);
    expect(panOf(1, 1, 1)).toBe(0);
  });

  it('the range skips values that are not finite', () => {
    expect(rangeOf([NaN, 2, -1, Infinity])).toEqual([-1, 2]);
    expect(rangeOf([NaN])).toEqual([0, 1]);
  });

  it('a stepped point says x, y, its events and where it is', () => {
    const xs = [0, 0.5, 1, 1.5, 2];
    const ys = xs.map((t) => t * t - 1);
    const events = [
      { x: 1, kind: 'root' as const },
      { x: 1.74, kind: 'kink' as const, label: 'the far hit' },
    ];
    expect(pointText(xs, ys, 2, 't', 'g', events, fmt)).toBe('t = 1, g = 0; root (point 3 of 5)');
    expect(pointText(xs, ys, 0, 't', 'g', events, fmt)).toBe('t = 0, g = −1 (point 1 of 5)');
    expect(pointText(xs, ys, 3, 't', 'g', events, fmt)).toBe('t = 1.5, g = 1.25; the far hit (point 4 of 5)');
    expect(pointText(xs, [NaN, 0, 0, 0, 0], 0, 't', 'g', [], fmt)).toBe('t = 0, g = no value (point 1 of 5)');
  });
});
