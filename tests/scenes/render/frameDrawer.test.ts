import { describe, expect, it } from 'vitest';
import { frameDrawer, type FrameClock } from '../../../src/scenes/render/frameDrawer';

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
