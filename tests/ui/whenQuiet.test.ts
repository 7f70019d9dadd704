import { describe, expect, it, vi } from 'vitest';
import { whenQuiet, type IdleApi } from '../../src/ui/whenQuiet';

/** A fake clock and idle scheduler: `busy(from, to)` marks spans where no idle period is whole. */
function fakeIdle(busySpans: Array<[number, number]>) {
  let t = 0;
  const timers: Array<{ at: number; cb: () => void }> = [];
  let pendingIdle: ((d: { timeRemaining: () => number; didTimeout: boolean }) => void) | null = null;
  const api: IdleApi = {
    request: (cb) => {
      pendingIdle = cb;
    },
    now: () => t,
    setTimeout: (cb, ms) => timers.push({ at: t + ms, cb }),
  };
  /** Advance in 50 ms idle periods until `until`; returns the time the promise settled (or null). */
  const run = async (p: Promise<void>, until: number) => {
    let settled: number | null = null;
    void p.then(() => {
      settled = t;
    });
    while (t < until && settled === null) {
      t += 50;
      for (const tm of timers.splice(0))
        if (tm.at <= t) tm.cb();
        else timers.push(tm);
      const busy = busySpans.some(([a, b]) => t >= a && t < b);
      const cb = pendingIdle;
      pendingIdle = null;
      if (cb) cb({ timeRemaining: () => (busy ? 3 : 49), didTimeout: false });
      await Promise.resolve();
      await Promise.resolve();
    }
    return settled;
  };
  return { api, run };
}

describe('whenQuiet', () => {
  it('resolves after quietMs of whole idle periods in a row', async () => {
    const { api, run } = fakeIdle([]);
    const at = await run(whenQuiet({ quietMs: 1000, maxMs: 30_000, api }), 10_000);
    expect(at).not.toBeNull();
    expect(at!).toBeGreaterThanOrEqual(1000);
    expect(at!).toBeLessThan(1300);
  });

  it('a busy stretch starts the count again', async () => {
    const { api, run } = fakeIdle([
      [0, 2000],
      [2600, 3000],
    ]);
    const at = await run(whenQuiet({ quietMs: 1000, maxMs: 30_000, api }), 10_000);
    expect(at!).toBeGreaterThanOrEqual(4000);
    expect(at!).toBeLessThan(4300);
  });

  it('a page that is never quiet still gets it after maxMs', async () => {
    const { api, run } = fakeIdle([[0, 1e9]]);
    const at = await run(whenQuiet({ quietMs: 1000, maxMs: 5000, api }), 10_000);
    expect(at!).toBeGreaterThanOrEqual(5000);
    expect(at!).toBeLessThan(5200);
  });
});

describe('readerActed and openingDone: the opening is over when the reader acts, whatever the page does', () => {
  it('a wheel (or key, press, touch) resolves both at once, and isOpeningDone says so; the listeners then go', async () => {
    const target = new EventTarget();
    const added: string[] = [];
    const removed: string[] = [];
    const win = Object.assign(target, {
      addEventListener: (t: string, f: EventListener, o?: AddEventListenerOptions) => {
        added.push(t);
        EventTarget.prototype.addEventListener.call(target, t, f, o);
      },
      removeEventListener: (t: string, f: EventListener, o?: boolean) => {
        removed.push(t);
        EventTarget.prototype.removeEventListener.call(target, t, f, o);
      },
    });
    vi.stubGlobal('window', win);
    // pageSettled waits for a painted frame that never comes here: only the reader can end the opening
    vi.stubGlobal('requestAnimationFrame', () => 0);
    vi.resetModules();
    try {
      const { readerActed, openingDone, isOpeningDone, READER_EVENTS } =
        await import('../../src/ui/whenQuiet');
      let over = false;
      void openingDone().then(() => (over = true));
      let acted = false;
      void readerActed().then(() => (acted = true));
      await new Promise((r) => setTimeout(r, 20));
      expect([over, acted, isOpeningDone()]).toEqual([false, false, false]);
      expect(added.sort()).toEqual([...READER_EVENTS].sort());
      target.dispatchEvent(new Event('wheel'));
      await new Promise((r) => setTimeout(r, 0));
      expect([over, acted, isOpeningDone()]).toEqual([true, true, true]);
      expect(removed.sort()).toEqual([...READER_EVENTS].sort());
    } finally {
      vi.unstubAllGlobals();
      vi.resetModules();
    }
  });
});
