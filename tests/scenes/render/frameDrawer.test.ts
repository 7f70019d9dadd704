import { describe, expect, it } from 'vitest';
import { frameDrawer, readoutGate, type FrameClock } from '../../../src/scenes/render/frameDrawer';

/**
 * A drawer on a clock whose frames come only when the test says so (`frame()`), counting its draws.
 */
function drawerOnFakeClock() {
  const queued = new Map<number, () => void>();
  let next = 1;
  const clock: FrameClock = {
    request: (cb) => {
      queued.set(next, cb);
      return next++;
    },
    cancel: (id) => void queued.delete(id),
  };
  let draws = 0;
  return {
    d: frameDrawer(() => draws++, clock),
    frame: () => {
      const cbs = [...queued.values()];
      queued.clear();
      cbs.forEach((cb) => cb());
    },
    pending: () => queued.size,
    draws: () => draws,
  };
}

describe('frameDrawer', () => {
  it('draws once per frame however many passes arrive before it', () => {
    const { d, frame, pending, draws } = drawerOnFakeClock();
    d.schedule();
    d.schedule();
    d.schedule();
    expect(pending()).toBe(1);
    frame();
    expect(draws()).toBe(1);
    d.schedule();
    frame();
    expect(draws()).toBe(2);
  });

  it('a run stopped after its last pass but before its frame draws the whole image then', () => {
    const { d, frame, pending, draws } = drawerOnFakeClock();
    d.schedule();
    d.complete();
    d.stop();
    expect(draws()).toBe(1);
    expect(pending()).toBe(0);
    frame();
    expect(draws()).toBe(1);
  });

  it('a run stopped before it is whole draws nothing more (it starts again from its first pass)', () => {
    const { d, frame, draws } = drawerOnFakeClock();
    d.schedule();
    d.stop();
    frame();
    expect(draws()).toBe(0);
  });

  it('a whole image already drawn is not drawn again when the run stops', () => {
    const { d, frame, draws } = drawerOnFakeClock();
    d.complete();
    frame();
    d.stop();
    expect(draws()).toBe(1);
  });
});

describe('readoutGate: the readouts at most 4 times a second, and always at the end', () => {
  function gate() {
    let t = 0;
    let shows = 0;
    const g = readoutGate(
      () => shows++,
      250,
      () => t,
    );
    return { g, at: (ms: number) => (t = ms), shows: () => shows };
  }

  it('shows the first frame, then skips frames until the interval has passed', () => {
    const { g, at, shows } = gate();
    at(0);
    g.frame();
    expect(shows()).toBe(1);
    for (const ms of [16, 100, 249]) {
      at(ms);
      g.frame();
    }
    expect(shows()).toBe(1);
    at(250);
    g.frame();
    expect(shows()).toBe(2);
    // sixty frames a second for two seconds: about eight more readouts, not 120
    for (let f = 1; f <= 120; f++) {
      at(250 + f * (1000 / 60));
      g.frame();
    }
    expect(shows()).toBeGreaterThanOrEqual(9);
    expect(shows()).toBeLessThanOrEqual(10);
  });

  it('shows the frame of the last pass at once, whenever it comes', () => {
    const { g, at, shows } = gate();
    g.frame();
    at(10);
    g.last();
    g.frame();
    expect(shows()).toBe(2);
  });

  it('a run stopped between two readouts shows what its last frame drew, once', () => {
    const { g, at, shows } = gate();
    g.frame();
    at(100);
    g.frame();
    expect(shows()).toBe(1);
    g.flush();
    expect(shows()).toBe(2);
    g.flush();
    expect(shows()).toBe(2);
  });

  it('a stop with nothing new since the last readout shows nothing more', () => {
    const { g, shows } = gate();
    g.frame();
    g.flush();
    expect(shows()).toBe(1);
  });
});
