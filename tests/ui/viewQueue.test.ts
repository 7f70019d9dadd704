import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { createViewQueue } from '../../src/ui/viewQueue';
import { FakeIO } from './fakeIO';

const idleCbs: ((d: { timeRemaining: () => number; didTimeout: boolean }) => void)[] = [];

beforeAll(() => {
  vi.stubGlobal('IntersectionObserver', FakeIO);
  vi.stubGlobal('requestIdleCallback', (cb: (typeof idleCbs)[number]) => idleCbs.push(cb));
});
afterAll(() => vi.unstubAllGlobals());

describe('createViewQueue: a job gets its element box as the observer last reported it', () => {
  it('near and idle jobs receive the reported width; a job with no report gets none', () => {
    const q = createViewQueue({
      margin: '0px',
      perIdle: 1,
      idleTimeoutMs: 100,
      runNear: (job) => (job(), () => {}),
    });
    const got: [string, number | undefined][] = [];
    const near = {} as Element;
    const far = {} as Element;
    const unseen = {} as Element;
    q.schedule(near, (r) => got.push(['near', r?.width]));
    q.schedule(far, (r) => got.push(['far', r?.width]));
    q.schedule(unseen, (r) => got.push(['unseen', r?.width]));
    const io = FakeIO.all[FakeIO.all.length - 1];
    io.report(near, true, 370);
    expect(got).toEqual([['near', 370]]);
    io.report(far, false, 412);
    for (const cb of idleCbs.splice(0)) cb({ timeRemaining: () => 50, didTimeout: false });
    expect(got).toEqual([
      ['near', 370],
      ['far', 412],
    ]);
    q.flush(); // never reported (e.g. printing before the observer answered)
    expect(got).toEqual([
      ['near', 370],
      ['far', 412],
      ['unseen', undefined],
    ]);
  });
});
