/**
 * The shared animation wiring (src/ui/animation.tsx): the store the animated parts read, the
 * still position, the text rate of frame writers, the throttle behind useThrottled and the
 * last-value cache.
 */
import { describe, expect, it } from 'vitest';
import {
  createAnimationStore,
  createThrottle,
  heldPosition,
  lastValue,
  textGate,
  type ThrottleClock,
} from '../../src/ui/animation';
import type { Timeline } from '../../src/ui';

const tl = (t: number, playing: boolean) => ({ t, playing }) as Timeline;

describe('animation store', () => {
  it('clamps the opening position into [0, max]', () => {
    expect(createAnimationStore(-3).t()).toBe(0);
    expect(createAnimationStore(Number.POSITIVE_INFINITY, 64).t()).toBe(0);
    expect(createAnimationStore(70, 64).t()).toBe(64);
    expect(createAnimationStore(12, 64).tStill()).toBe(12);
  });

  it('holds the still position from play to pause; seeks while paused move it', () => {
    const s = createAnimationStore(0.1);
    const seen: number[] = [];
    s.subscribe(() => seen.push(s.tStill()));
    s.publish(tl(0.25, false)); // a seek while paused
    s.publish(tl(0.25, true));
    s.publish(tl(0.5, true));
    s.publish(tl(0.75, true));
    s.publish(tl(0.8, false));
    expect(seen).toEqual([0.25, 0.25, 0.25, 0.25, 0.8]);
    expect(heldPosition(0.9, true, 0.25)).toBe(0.25);
    expect(heldPosition(0.9, false, 0.25)).toBe(0.9);
  });

  it('frames carry the live position and playing state without notifying render listeners', () => {
    const s = createAnimationStore(0);
    let renders = 0;
    s.subscribe(() => renders++);
    const frames: number[] = [];
    const off = s.subscribeFrame((x) => frames.push(x));
    s.frame(0.1, true);
    s.frame(0.2);
    expect(frames).toEqual([0.1, 0.2]);
    expect(s.tLive()).toBe(0.2);
    expect(s.livePlaying()).toBe(true);
    s.frame(0.3, false);
    expect(s.livePlaying()).toBe(false);
    off();
    s.frame(0.4);
    expect(frames).toEqual([0.1, 0.2, 0.3]);
    expect(renders).toBe(0);
  });
});

describe('textGate', () => {
  it('lets text through on every paused frame and at most hz times a second while playing', () => {
    const gate = textGate(4);
    expect([0, 1, 2].map((t) => gate(false, t))).toEqual([true, true, true]);
    const playing = [];
    for (let now = 100; now <= 1100; now += 16) if (gate(true, now)) playing.push(now);
    expect(playing.length).toBeGreaterThanOrEqual(4);
    expect(playing.length).toBeLessThanOrEqual(5);
    for (let i = 1; i < playing.length; i++)
      expect(playing[i]! - playing[i - 1]!).toBeGreaterThanOrEqual(249);
    expect(gate(false, 1101)).toBe(true); // pausing shows the exact text at once
  });
});

/** A clock whose time moves only when the test says so. */
function fakeClock() {
  let now = 0;
  let timers: { at: number; fn: () => void; id: number }[] = [];
  let next = 1;
  const clock: ThrottleClock = {
    now: () => now,
    setTimeout: (fn, ms) => {
      const id = next++;
      timers.push({ at: now + ms, fn, id });
      return id;
    },
    clearTimeout: (id) => {
      timers = timers.filter((t) => t.id !== id);
    },
  };
  const advance = (ms: number) => {
    const end = now + ms;
    for (;;) {
      timers.sort((a, b) => a.at - b.at);
      const t = timers[0];
      if (!t || t.at > end) break;
      timers.shift();
      now = t.at;
      t.fn();
    }
    now = end;
  };
  return { clock, advance, pending: () => timers.length };
}

describe('createThrottle (useThrottled)', () => {
  it('shows a value after a quiet interval at once, and the latest of a burst one interval later', () => {
    const { clock, advance } = fakeClock();
    const shown: [number, string][] = [];
    const th = createThrottle<string>(200, (v) => shown.push([clock.now(), v]), clock);
    advance(1000);
    th.push('a');
    advance(50);
    th.push('b');
    advance(50);
    th.push('c');
    expect(shown).toEqual([[1000, 'a']]);
    advance(100);
    expect(shown).toEqual([
      [1000, 'a'],
      [1200, 'c'],
    ]);
    advance(500);
    th.push('d'); // quiet again: leading edge
    expect(shown.at(-1)).toEqual([1700, 'd']);
  });

  it('immediate shows at once and drops the pending value; dispose drops it too', () => {
    const { clock, advance, pending } = fakeClock();
    const shown: string[] = [];
    const th = createThrottle<string>(400, (v) => shown.push(v), clock);
    advance(1000);
    th.push('partial 1');
    advance(10);
    th.push('partial 2');
    expect(pending()).toBe(1);
    th.push('final', true);
    expect(pending()).toBe(0);
    advance(1000);
    expect(shown).toEqual(['partial 1', 'final']);
    advance(10);
    th.push('x');
    advance(10);
    th.push('y');
    th.dispose();
    advance(1000);
    expect(shown).toEqual(['partial 1', 'final', 'x']);
  });
});

describe('lastValue', () => {
  it('computes once per distinct argument in a row and returns the same result for the same t', () => {
    let calls = 0;
    const f = lastValue((t) => {
      calls++;
      return { t };
    });
    const a = f(0.5);
    expect(f(0.5)).toBe(a);
    expect(calls).toBe(1);
    expect(f(0.6)).toEqual({ t: 0.6 });
    expect(f(0.5)).not.toBe(a);
    expect(calls).toBe(3);
    let n = 0; // an undefined result is remembered too
    const h = lastValue(() => (n++, undefined));
    h(1);
    h(1);
    expect(n).toBe(1);
  });
});
