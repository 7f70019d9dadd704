import { describe, expect, it } from 'vitest';
import { runChunked, SLICE_MS } from '../../src/ui/chunked';

const settle = () => new Promise((r) => setTimeout(r, 50));
/** Wait (polling, up to 10 s on a loaded machine) until `cond` holds: a state, not a fixed time. */
async function until(cond: () => boolean): Promise<void> {
  const end = Date.now() + 10_000;
  while (!cond() && Date.now() < end) await settle();
}

describe('runChunked', () => {
  it('runs queued jobs later, in order, not synchronously', async () => {
    const seen: number[] = [];
    for (let i = 0; i < 5; i++) runChunked(() => seen.push(i));
    expect(seen).toEqual([]);
    await until(() => seen.length === 5);
    expect(seen).toEqual([0, 1, 2, 3, 4]);
  });

  it('a cancelled job does not run; the others do', async () => {
    const seen: string[] = [];
    runChunked(() => seen.push('a'));
    const cancel = runChunked(() => seen.push('b'));
    runChunked(() => seen.push('c'));
    cancel();
    await until(() => seen.includes('c'));
    expect(seen).toEqual(['a', 'c']);
  });

  it('yields between slices: jobs that each take ~SLICE_MS run in separate tasks', async () => {
    const task: number[] = [];
    let currentTask = 0;
    // a macrotask counter: each timer tick marks a new task boundary
    const ticker = setInterval(() => currentTask++, 0);
    const busy = (ms: number) => {
      const t0 = performance.now();
      while (performance.now() - t0 < ms) {
        /* spin */
      }
    };
    const done = new Promise<void>((resolve) => {
      for (let i = 0; i < 4; i++)
        runChunked(() => {
          busy(SLICE_MS + 1);
          task.push(currentTask);
          if (i === 3) resolve();
        });
    });
    await done;
    clearInterval(ticker);
    // one slice holds at most one over-budget job, so the four jobs ran in four different tasks
    expect(new Set(task).size).toBe(4);
  });

  it('a throwing job does not stop the queue', async () => {
    const seen: string[] = [];
    const errors: unknown[] = [];
    const onErr = (e: unknown) => errors.push(e);
    process.on('uncaughtException', onErr);
    runChunked(() => {
      throw new Error('boom');
    });
    runChunked(() => seen.push('after'));
    await until(() => seen.length > 0 && errors.length > 0);
    process.off('uncaughtException', onErr);
    expect(seen).toEqual(['after']);
    expect(errors.length).toBe(1);
  });
});
