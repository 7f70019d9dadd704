/**
 * The KaTeX worker (./katex.worker.ts): its one factory, the page's one instance, and typesetting
 * a formula in it. ./MathTex.tsx falls back to KaTeX on the main thread where it cannot start.
 */
import type { TypesetReply, TypesetRequest } from './katex.worker';

/** Starts a KaTeX worker: the one place that names the worker's file. */
export function createKatexWorker(): Worker {
  return new Worker(new URL('./katex.worker.ts', import.meta.url), { type: 'module' });
}

let worker: Worker | null | undefined;
let nextId = 1;
const waiting = new Map<number, { resolve: (html: string | null) => void; reject: (e: unknown) => void }>();

/**
 * The page's KaTeX worker, started on first use: one aligned derivation is tens of ms of KaTeX on
 * a phone, a long task each on the main thread. Null where no worker can be started (or it failed
 * to load); KaTeX then runs on the main thread.
 */
export function katexWorker(): Worker | null {
  if (worker !== undefined) return worker;
  try {
    worker = createKatexWorker();
    worker.onmessage = (e: MessageEvent<TypesetReply>) => {
      const w = waiting.get(e.data.id);
      waiting.delete(e.data.id);
      w?.resolve(e.data.html);
    };
    worker.onerror = (e) => {
      // the worker could not load: the rest is typeset on the main thread
      e.preventDefault();
      worker?.terminate();
      worker = null;
      const left = [...waiting.values()];
      waiting.clear();
      for (const w of left) w.reject(new Error('the KaTeX worker could not start'));
    };
  } catch {
    worker = null;
  }
  return worker;
}

/**
 * HTML for `tex` typeset in the page's worker (null if KaTeX fails on it); rejects when the
 * worker cannot start or dies before answering.
 */
export function typesetInWorker(tex: string, display: boolean): Promise<string | null> {
  const w = katexWorker();
  if (!w) return Promise.reject(new Error('no KaTeX worker'));
  return new Promise<string | null>((resolve, reject) => {
    const id = nextId++;
    waiting.set(id, { resolve, reject });
    w.postMessage({ id, tex, display } satisfies TypesetRequest);
  });
}
