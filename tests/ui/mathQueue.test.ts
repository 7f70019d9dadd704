import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { FakeIO } from './fakeIO';

const idleCbs: ((d: { timeRemaining: () => number; didTimeout: boolean }) => void)[] = [];
const runIdle = () => {
  const cbs = idleCbs.splice(0);
  for (const cb of cbs) cb({ timeRemaining: () => 50, didTimeout: false });
};
const settle = () => new Promise((r) => setTimeout(r, 30));

// the page's "settled" moment (src/ui/whenQuiet.ts), opened by the test
const page = vi.hoisted(() => {
  let open = () => {};
  const settled = new Promise<void>((r) => (open = r));
  return { settled, open: () => open() };
});
vi.mock('../../src/ui/whenQuiet', () => ({ openingDone: () => page.settled }));

beforeAll(() => {
  // a fresh mathQueue, bound to the whenQuiet mock above: the unit run shares one module cache per
  // worker thread (vitest.config.ts, isolate: false), where another test file may have loaded the
  // real one first
  vi.resetModules();
  vi.stubGlobal('IntersectionObserver', FakeIO);
  vi.stubGlobal('requestIdleCallback', (cb: (typeof idleCbs)[number]) => idleCbs.push(cb));
});
afterAll(() => vi.unstubAllGlobals());

describe('scheduleMath: formulas near the screen first, the rest in idle time', () => {
  it('near ones run soon; far ones only in idle time once the page has settled, a few per idle period, in order; a far one that scrolls near is promoted', async () => {
    const { scheduleMath } = await import('../../src/ui/mathQueue');
    const seen: string[] = [];
    const els = Array.from({ length: 8 }, () => ({}) as Element);
    els.forEach((el, i) => scheduleMath(el, () => seen.push(`f${i}`)));
    const io = FakeIO.all[0];
    // nothing runs before the observer has said where each formula is
    await settle();
    expect(seen).toEqual([]);
    io.report(els[0], true);
    for (let i = 1; i < 8; i++) io.report(els[i], false);
    await settle();
    expect(seen).toEqual(['f0']); // the near one, without waiting for idle time
    io.report(els[6], true); // scrolled near: promoted
    await settle();
    expect(seen).toEqual(['f0', 'f6']);
    runIdle(); // the page is still opening: far formulas wait until it has settled
    await settle();
    expect(seen).toEqual(['f0', 'f6']);
    page.open();
    await settle();
    runIdle();
    expect(seen).toEqual(['f0', 'f6', 'f1', 'f2', 'f3', 'f4']); // four per idle period, in page order
    runIdle();
    expect(seen).toEqual(['f0', 'f6', 'f1', 'f2', 'f3', 'f4', 'f5', 'f7']);
    expect(io.observed.size).toBe(0); // done formulas are no longer observed
  });

  it('a cancelled formula never runs; an element known to be near runs its next formula at once', async () => {
    const { scheduleMath } = await import('../../src/ui/mathQueue');
    const io = FakeIO.all[0];
    const seen: string[] = [];
    const a = {} as Element;
    const b = {} as Element;
    scheduleMath(a, () => seen.push('a1'));
    const cancelB = scheduleMath(b, () => seen.push('b1'));
    io.report(a, true);
    io.report(b, false);
    cancelB();
    runIdle();
    await settle();
    expect(seen).toEqual(['a1']);
    scheduleMath(a, () => seen.push('a2')); // live numbers changed on screen
    await settle();
    expect(seen).toEqual(['a1', 'a2']);
  });

  it('flushMathForPrint runs everything still waiting, synchronously', async () => {
    const { scheduleMath, flushMathForPrint } = await import('../../src/ui/mathQueue');
    const io = FakeIO.all[0];
    const seen: string[] = [];
    const a = {} as Element;
    const b = {} as Element;
    const c = {} as Element;
    scheduleMath(c, () => seen.push('c1'));
    io.report(c, true);
    await settle();
    seen.length = 0;
    scheduleMath(a, () => seen.push('a'));
    scheduleMath(b, () => seen.push('b'));
    scheduleMath(c, () => seen.push('c2')); // c is known to be near: queued in its slice at once
    io.report(b, false); // b waits for idle time, a has no report yet
    flushMathForPrint();
    expect(seen.sort()).toEqual(['a', 'b', 'c2']);
    runIdle();
    await settle();
    expect(seen.length).toBe(3); // nothing runs twice
  });
});

describe('insertTypeset: typeset formulas go into the page a few per painted frame', () => {
  it('batches by HTML length, one batch per frame; one formula over the limit still goes alone; a failing insert does not stop the rest', async () => {
    const frames: (() => void)[] = [];
    vi.stubGlobal('requestAnimationFrame', (cb: () => void) => frames.push(cb));
    const paint = async () => {
      for (const cb of frames.splice(0)) cb();
      await settle();
    };
    const { insertTypeset, HTML_PER_FRAME } = await import('../../src/ui/mathQueue');
    const seen: string[] = [];
    const third = Math.floor(HTML_PER_FRAME / 3);
    const thrown: unknown[] = [];
    const onErr = (e: unknown) => thrown.push(e);
    process.on('uncaughtException', onErr);
    try {
      insertTypeset(third, () => seen.push('a'));
      insertTypeset(third, () => seen.push('b'));
      insertTypeset(third, () => {
        seen.push('c');
        throw new Error('boom');
      });
      insertTypeset(third, () => seen.push('d'));
      insertTypeset(3 * HTML_PER_FRAME, () => seen.push('big'));
      insertTypeset(1, () => seen.push('e'));
      expect(seen).toEqual([]); // never inside the caller's task
      await settle();
      expect(seen).toEqual(['a', 'b', 'c']); // the first three fit; the fourth would pass the limit
      await settle();
      expect(seen).toEqual(['a', 'b', 'c']); // nothing more before a frame is painted
      await paint();
      expect(seen).toEqual(['a', 'b', 'c', 'd']); // d, then big would pass the limit
      await paint();
      expect(seen).toEqual(['a', 'b', 'c', 'd', 'big']); // alone, though over the limit
      await paint();
      expect(seen).toEqual(['a', 'b', 'c', 'd', 'big', 'e']);
      await paint();
      expect(thrown.map((e) => (e as Error).message)).toEqual(['boom']);
      insertTypeset(1, () => seen.push('f')); // an idle queue takes the next one after a task
      await settle();
      expect(seen.at(-1)).toBe('f');
    } finally {
      process.off('uncaughtException', onErr);
    }
  });
});
