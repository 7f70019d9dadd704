/** A `window` with in-memory localStorage and sessionStorage, for the storage modules' tests. */
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
