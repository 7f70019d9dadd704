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

describe('createViewQueue: idle-time jobs wait for `idleAfter`, near ones never do', () => {
  it('a far job runs in no idle period before the promise resolves, then in the next; a near one runs at once throughout', async () => {
    let open = () => {};
    const opened = new Promise<void>((r) => (open = r));
    let asked = 0;
    const q = createViewQueue({
      margin: '0px',
      perIdle: 4,
      idleTimeoutMs: 100,
      runNear: (job) => (job(), () => {}),
      idleAfter: () => (asked++, opened),
    });
    const got: string[] = [];
    const near = {} as Element;
    const far1 = {} as Element;
    const far2 = {} as Element;
    q.schedule(far1, () => got.push('far1'));
    q.schedule(far2, () => got.push('far2'));
    q.schedule(near, () => got.push('near'));
    const io = FakeIO.all[FakeIO.all.length - 1];
    io.report(far1, false);
    io.report(far2, false);
    io.report(near, true);
    expect(got).toEqual(['near']);
    expect(asked).toBe(1); // asked once, however many jobs wait
    // the page is idle between its opening's frames: nothing far runs yet
    for (const cb of idleCbs.splice(0)) cb({ timeRemaining: () => 50, didTimeout: false });
    await Promise.resolve();
    expect(got).toEqual(['near']);
    // a far job that scrolls near does not wait
    io.report(far2, true);
    expect(got).toEqual(['near', 'far2']);
    open();
    await opened;
    await Promise.resolve();
    expect(got).toEqual(['near', 'far2']); // not inside the promise's callback: in idle time
    for (const cb of idleCbs.splice(0)) cb({ timeRemaining: () => 50, didTimeout: false });
    expect(got).toEqual(['near', 'far2', 'far1']);
  });

  it('a rejected promise opens idle time too (the jobs are not lost)', async () => {
    const q = createViewQueue({
      margin: '0px',
      perIdle: 1,
      idleTimeoutMs: 100,
      runNear: (job) => (job(), () => {}),
      idleAfter: () => Promise.reject(new Error('no idle detection')),
    });
    const got: string[] = [];
    const far = {} as Element;
    q.schedule(far, () => got.push('far'));
    FakeIO.all[FakeIO.all.length - 1].report(far, false);
    await new Promise((r) => setTimeout(r, 0));
    for (const cb of idleCbs.splice(0)) cb({ timeRemaining: () => 50, didTimeout: false });
    expect(got).toEqual(['far']);
  });
});
