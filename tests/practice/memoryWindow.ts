/** A `window` with in-memory localStorage and sessionStorage, for the storage modules' tests. */
import { afterEach, beforeEach } from 'vitest';
import { setLearnerScope } from '../../src/practice/learnerScope';

export class MemoryStorage {
  data = new Map<string, string>();
  getItem(k: string) {
    return this.data.has(k) ? this.data.get(k)! : null;
  }
  setItem(k: string, v: string) {
    this.data.set(k, v);
  }
  removeItem(k: string) {
    this.data.delete(k);
  }
}

const g = globalThis as unknown as { window?: unknown };

/** Install a window whose storages are `local` and `session`; returns its removal. */
export function installWindow(local = new MemoryStorage(), session = new MemoryStorage()): () => void {
  const listeners: Record<string, ((e: Event) => void)[]> = {};
  g.window = {
    localStorage: local,
    sessionStorage: session,
    addEventListener: (t: string, f: (e: Event) => void) => (listeners[t] ??= []).push(f),
    removeEventListener: () => undefined,
    dispatchEvent: (e: Event) => {
      for (const f of listeners[e.type] ?? []) f(e);
      return true;
    },
  };
  return () => delete g.window;
}

/**
 * For a test file of the storage modules: before each test a fresh window of in-memory storages
 * and no learner scope, both taken away after it. The object returned holds the current test's
 * storages.
 */
export function freshWindowEachTest(): { local: MemoryStorage; session: MemoryStorage } {
  const current = { local: new MemoryStorage(), session: new MemoryStorage() };
  let remove = () => {};
  beforeEach(() => {
    current.local = new MemoryStorage();
    current.session = new MemoryStorage();
    remove = installWindow(current.local, current.session);
    setLearnerScope(null);
  });
  afterEach(() => {
    setLearnerScope(null);
    remove();
  });
  return current;
}
