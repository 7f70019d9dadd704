/**
 * The results page's worker: the real task module behind an in-process stand-in for a Worker
 * (messages as a worker would get them), one worker for several batches, progress naming each
 * file, a worker that dies named by the file it was checking, and Cancel.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { collate } from '../../src/results/collate';
import { CollationFailed, ResultsChecker } from '../../src/results/jobs';

type Listener = ((e: MessageEvent) => void) | null;
/** The worker's global scope: exposeTasks sets its onmessage; its postMessage reaches the page. */
const scope: { onmessage: Listener; postMessage: (m: unknown) => void } = {
  onmessage: null,
  postMessage: () => undefined,
};

/** A Worker running the task module in this thread; `die` makes it fail after `n` messages. */
class InProcessWorker {
  onmessage: Listener = null;
  onerror: ((e: { message: string; preventDefault(): void }) => void) | null = null;
  terminated = false;
  constructor(private die?: { after: number }) {
    let sent = 0;
    scope.postMessage = (m) => {
      if (this.terminated) return;
      if (this.die && sent++ >= this.die.after) {
        this.terminated = true;
        queueMicrotask(() => this.onerror?.({ message: 'out of memory', preventDefault: () => undefined }));
        return;
      }
      queueMicrotask(() => this.onmessage?.({ data: m } as MessageEvent));
    };
  }
  postMessage(m: unknown) {
    queueMicrotask(() => scope.onmessage?.({ data: m } as MessageEvent));
  }
  terminate() {
    this.terminated = true;
  }
}

beforeAll(async () => {
  (globalThis as unknown as { self: unknown }).self = scope;
  await import('../../src/results/results.worker');
});
afterAll(() => {
  delete (globalThis as unknown as { self?: unknown }).self;
});

const file = (student: string, n: number) =>
  JSON.stringify({
    format: 'render-math-lab-results',
    formatVersion: 1,
    student,
    attempts: Array.from({ length: n }, (_, i) => ({
      question: 'q3',
      seed: i + 1,
      time: `2026-01-01T00:00:${String(i).padStart(2, '0')}Z`,
      answers: { 'u-nearest': String(i / 10) },
      verdicts: {},
    })),
  });

const files = [
  { name: 'ada.json', text: file('Ada', 3) },
  { name: 'bob.json', text: file('Bob', 2) },
  { name: 'cy.json', text: file('Cy', 1) },
];

describe('collation in the results worker', () => {
  it('gives what collate gives, naming each file as it starts, batch after batch in one worker', async () => {
    const made: InProcessWorker[] = [];
    const checker = new ResultsChecker(() => {
      made.push(new InProcessWorker());
      return made[made.length - 1] as unknown as Worker;
    });
    await checker.warm();
    const seen: string[] = [];
    const c = await checker.collate(
      files,
      (s) => s.current && seen.push(s.current),
      new AbortController().signal,
    );
    expect(seen).toEqual(['ada.json', 'bob.json', 'cy.json']);
    expect(c).toEqual(await collate(files));
    expect(c.attempts).toBe(6);
    const c2 = await checker.collate(files.slice(1), () => undefined, new AbortController().signal);
    expect(c2.attempts).toBe(3);
    expect(made).toHaveLength(1);
    expect(made[0].terminated).toBe(false);
  });
  it('a worker that dies is reported with the file it was checking', async () => {
    // messages: start ada, done ada, start bob, then the worker dies
    const checker = new ResultsChecker(() => new InProcessWorker({ after: 3 }) as unknown as Worker);
    const p = checker.collate(files, () => undefined, new AbortController().signal);
    await expect(p).rejects.toBeInstanceOf(CollationFailed);
    await expect(p).rejects.toMatchObject({ file: 'bob.json' });
    await expect(p).rejects.toThrow(/^Checking stopped at bob\.json: out of memory\.$/);
  });
  it('Cancel ends the worker at once; the next batch starts another', async () => {
    const made: InProcessWorker[] = [];
    const checker = new ResultsChecker(() => {
      made.push(new InProcessWorker());
      return made[made.length - 1] as unknown as Worker;
    });
    const ctl = new AbortController();
    const p = checker.collate(files, (s) => s.current === 'bob.json' && ctl.abort(), ctl.signal);
    await expect(p).rejects.toMatchObject({ name: 'AbortError' });
    expect(made[0].terminated).toBe(true);
    const c = await checker.collate(files, () => undefined, new AbortController().signal);
    expect(c.attempts).toBe(6);
    expect(made).toHaveLength(2);
  });
});
