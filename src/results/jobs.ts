/**
 * Collating the class's results files in the results page's worker (./results.worker.ts): the one
 * factory that starts it, and the page's checker. A crafted file can make grading slow (every
 * attempt is checked again from its typed text); in the worker it holds up nothing on the page.
 *
 * The page keeps one worker for its life, warmed when the page opens (the answer checker loaded
 * then, so collating needs no request later: the page works offline once open). Cancel ends the
 * worker at once (terminate); the next batch starts a new one.
 */
import { FailureError } from '../core/failure';
import { workerFactory, type FromWorker, type ToWorker } from '../workers/protocol';
import { TaskCancelled } from '../workers/run';
import type { Collation, InputFile } from './collate';
import type { CollateStep, ResultsTasks } from './results.worker';

/** Starts a results worker: the one place that names the worker's file. */
export const makeResultsWorker = workerFactory<ResultsTasks>(
  () => new Worker(new URL('./results.worker.ts', import.meta.url), { type: 'module' }),
);

/** A collation that stopped: `file` is the file it was checking (null between files). */
export class CollationFailed extends Error {
  constructor(
    readonly file: string | null,
    reason: string,
  ) {
    super(file ? `Checking stopped at ${file}: ${reason}.` : `Checking stopped: ${reason}.`);
    this.name = 'CollationFailed';
  }
}

interface Pending {
  resolve: (v: unknown) => void;
  reject: (e: unknown) => void;
  onStep?: (s: CollateStep) => void;
  current: string | null;
}

/** The results page's worker, kept between batches; see the module comment. */
export class ResultsChecker {
  private worker: Worker | null = null;
  private pending = new Map<number, Pending>();
  private nextId = 1;

  constructor(private readonly make: () => Worker = makeResultsWorker) {}

  /** Start the worker and load the answer checker in it (rejects when it cannot). */
  warm(): Promise<void> {
    return this.run('warm', null).then(() => undefined);
  }

  /**
   * Collate `files`; `onStep` hears of each file as it starts and ends. Rejects with an AbortError
   * when `signal` aborts (the worker is ended at once), and with {@link CollationFailed} (naming the
   * file it was on) when the worker cannot start, refuses or dies.
   */
  collate(files: InputFile[], onStep: (s: CollateStep) => void, signal: AbortSignal): Promise<Collation> {
    return this.run('collate', files, onStep, signal) as Promise<Collation>;
  }

  /** End the worker (the page is closing). */
  dispose(failure: unknown = new TaskCancelled()): void {
    this.worker?.terminate();
    this.worker = null;
    const left = [...this.pending.values()];
    this.pending.clear();
    for (const p of left) p.reject(failure instanceof TaskCancelled ? failure : this.failed(p, failure));
  }

  private failed(p: Pending, e: unknown): CollationFailed {
    return new CollationFailed(p.current, e instanceof Error ? e.message : String(e));
  }

  private start(): Worker {
    if (this.worker) return this.worker;
    const w = this.make();
    w.onmessage = (e: MessageEvent<FromWorker>) => {
      const m = e.data;
      const p = this.pending.get(m.id);
      if (!p) return;
      if (m.type === 'progress') {
        const step = m.partial as CollateStep | undefined;
        if (!step) return;
        p.current = step.current ?? null;
        p.onStep?.(step);
        return;
      }
      this.pending.delete(m.id);
      if (m.type === 'result') p.resolve(m.value);
      else p.reject(this.failed(p, new FailureError(m.kind, m.message)));
    };
    w.onerror = (e) => {
      e.preventDefault();
      this.dispose(new Error(e.message || 'the worker stopped'));
    };
    this.worker = w;
    return w;
  }

  private run(
    method: keyof ResultsTasks,
    args: unknown,
    onStep?: (s: CollateStep) => void,
    signal?: AbortSignal,
  ): Promise<unknown> {
    return new Promise((resolve, reject) => {
      if (signal?.aborted) return reject(new TaskCancelled());
      let w: Worker;
      try {
        w = this.start();
      } catch (e) {
        return reject(new CollationFailed(null, e instanceof Error ? e.message : String(e)));
      }
      const id = this.nextId++;
      this.pending.set(id, { resolve, reject, onStep, current: null });
      signal?.addEventListener('abort', () => this.pending.has(id) && this.dispose(), { once: true });
      w.postMessage({ id, method, args } satisfies ToWorker);
    });
  }
}
