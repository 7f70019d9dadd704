/**
 * The worker task protocol, exercised with an in-process fake Worker: progress, results with
 * transferred typed arrays, errors, and cancellation (terminate).
 */
import { afterEach, describe, expect, it } from 'vitest';
import { exposeTasks, yieldToEventLoop } from '../../src/workers/expose';
import { isCancelled, runWorkerTask } from '../../src/workers/run';
import { collectTransferables, workerFactory } from '../../src/workers/protocol';

class FakeWorker {
  onmessage: ((e: MessageEvent) => void) | null = null;
  onerror: ((e: ErrorEvent) => void) | null = null;
  terminated = false;
  transfers: Transferable[][] = [];
  private inner: {
    onmessage: ((e: MessageEvent) => void) | null;
    postMessage: (m: unknown, t?: Transferable[]) => void;
  };
  constructor(tasks: Parameters<typeof exposeTasks>[0]) {
    this.inner = {
      onmessage: null,
      postMessage: (m, t = []) => {
        this.transfers.push(t);
        if (!this.terminated) queueMicrotask(() => this.onmessage?.({ data: m } as MessageEvent));
      },
    };
    (globalThis as unknown as { self: unknown }).self = this.inner;
    exposeTasks(tasks);
  }
  postMessage(m: unknown) {
    queueMicrotask(() => this.inner.onmessage?.({ data: m } as MessageEvent));
  }
  terminate() {
    this.terminated = true;
  }
}

afterEach(() => {
  delete (globalThis as unknown as { self?: unknown }).self;
});

const tasks = {
  sum: async (args: { n: number }, progress: (f: number, p?: unknown) => void) => {
    const out = new Float64Array(args.n);
    for (let i = 0; i < args.n; i++) {
      out[i] = i;
      if (i % 10 === 9) {
        progress((i + 1) / args.n, { done: i + 1 });
        await yieldToEventLoop();
      }
    }
    return { total: out.reduce((a, b) => a + b, 0), values: out };
  },
  fail: async () => {
    throw new Error('density is negative');
  },
  forever: async (_: unknown, progress: (f: number) => void) => {
    for (let i = 0; ; i++) {
      progress(0);
      await yieldToEventLoop();
      if (i > 1e6) return 0;
    }
  },
};

describe('runWorkerTask', () => {
  it('reports progress in order and resolves with the result, transferring typed arrays', async () => {
    let w!: FakeWorker;
    const seen: number[] = [];
    const r = await runWorkerTask(
      workerFactory<typeof tasks>(() => (w = new FakeWorker(tasks)) as unknown as Worker),
      'sum',
      { n: 40 },
      {
        onProgress: (f) => seen.push(f),
      },
    );
    expect(r.total).toBe((39 * 40) / 2);
    expect(r.values.length).toBe(40);
    expect(seen).toEqual([0.25, 0.5, 0.75, 1]);
    expect(w.transfers.at(-1)).toContain(r.values.buffer);
    expect(w.terminated).toBe(true);
  });

  it('rejects with the task’s message on error', async () => {
    await expect(
      runWorkerTask(
        workerFactory<typeof tasks>(() => new FakeWorker(tasks) as unknown as Worker),
        'fail',
        undefined,
      ),
    ).rejects.toThrow('density is negative');
  });

  it('rejects unknown tasks', async () => {
    await expect(
      runWorkerTask(
        workerFactory<typeof tasks>(() => new FakeWorker(tasks) as unknown as Worker),
        'nope' as 'fail',
        undefined,
      ),
    ).rejects.toThrow(/unknown task/);
  });

  it('cancels: terminates the worker and rejects with an AbortError', async () => {
    let w!: FakeWorker;
    const ctl = new AbortController();
    const p = runWorkerTask(
      workerFactory<typeof tasks>(() => (w = new FakeWorker(tasks)) as unknown as Worker),
      'forever',
      {},
      { signal: ctl.signal },
    );
    await new Promise((r) => setTimeout(r, 5));
    ctl.abort();
    const err = await p.catch((e) => e);
    expect(isCancelled(err)).toBe(true);
    expect(w.terminated).toBe(true);
  });

  it('does not start when already cancelled', async () => {
    const ctl = new AbortController();
    ctl.abort();
    let made = false;
    const err = await runWorkerTask(
      workerFactory<typeof tasks>(() => ((made = true), new FakeWorker(tasks)) as unknown as Worker),
      'sum',
      { n: 1 },
      { signal: ctl.signal },
    ).catch((e) => e);
    expect(isCancelled(err)).toBe(true);
    expect(made).toBe(false);
  });
});

describe('collectTransferables', () => {
  it('finds typed-array buffers nested in results, once each', () => {
    const a = new Float64Array(4);
    const b = new Uint8Array(2);
    const list = collectTransferables({ a, nested: { b, again: a }, n: 3, s: 'x' });
    expect(list).toHaveLength(2);
    expect(list).toContain(a.buffer);
    expect(list).toContain(b.buffer);
  });
});
