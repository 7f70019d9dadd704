/**
 * The page's one polite live region. Every spoken status that is not a form's own message goes
 * through `announce()`: the region is created on first use (visually hidden, role="status"), and
 * texts reach it at most about once a second; a text that arrives while one is queued replaces it,
 * so a screen reader hears the settled state, not every step of a drag.
 */

/** Shortest gap between two texts written to the live region, in ms. */
export const ANNOUNCE_GAP_MS = 1000;

export interface Announcement {
  text: string;
  /** Date.now() when it was written to the live region. */
  at: number;
  /** 1, 2, 3, … in the order written. */
  seq: number;
}

type Listener = (a: Announcement) => void;

let region: HTMLElement | null = null;
let lastAt = -Infinity;
let queued: string | null = null;
let timer: ReturnType<typeof setTimeout> | null = null;
let flip = false;
const listeners = new Set<Listener>();
const history: Announcement[] = [];
const HISTORY_MAX = 50;

function liveRegion(): HTMLElement | null {
  if (typeof document === 'undefined') return null;
  if (region && region.isConnected) return region;
  region = document.createElement('div');
  region.className = 'sr-only';
  region.setAttribute('role', 'status');
  region.setAttribute('aria-live', 'polite');
  region.setAttribute('aria-atomic', 'true');
  region.dataset.testid = 'live-region';
  document.body.appendChild(region);
  return region;
}

let seq = 0;
const now = () => Date.now();

function write(text: string) {
  const el = liveRegion();
  lastAt = now();
  if (el) {
    // the same text twice would not be re-read: alternate an invisible trailing space
    flip = !flip;
    el.textContent = flip ? text : `${text}\u00a0`;
  }
  const a = { text, at: lastAt, seq: ++seq };
  history.push(a);
  if (history.length > HISTORY_MAX) history.shift();
  for (const l of listeners) l(a);
}

function flush() {
  timer = null;
  if (queued === null) return;
  const text = queued;
  queued = null;
  write(text);
}

/**
 * Speak `text` through the live region: now if the last text was at least a second ago (or with
 * `now: true`), else at the end of that second, replacing any text still waiting.
 */
export function announce(text: string, opts?: { now?: boolean }): void {
  const t = text.trim();
  if (!t) return;
  const wait = lastAt + ANNOUNCE_GAP_MS - now();
  if (opts?.now || wait <= 0) {
    if (timer !== null) clearTimeout(timer);
    timer = null;
    queued = null;
    write(t);
    return;
  }
  queued = t;
  timer ??= setTimeout(flush, wait);
}

/** Listen to what is written to the live region (the A11y view); returns the unsubscribe. */
export function onAnnounce(listener: Listener): () => void {
  listeners.add(listener);
  return () => listeners.delete(listener);
}

/** The last texts written to the live region, oldest first. */
export function recentAnnouncements(): readonly Announcement[] {
  return history;
}

/** Drop the queue and the history (tests; leaving a page). */
export function resetAnnouncer(): void {
  if (timer !== null) clearTimeout(timer);
  timer = null;
  queued = null;
  lastAt = -Infinity;
  history.length = 0;
  if (region) region.textContent = '';
}
