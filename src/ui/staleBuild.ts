/**
 * A page of an old build after a new one was deployed: its lazy chunks may be gone (the new build's
 * service worker precaches only its own files, and the host has replaced the folder). A failed
 * dynamic import is then not a broken page but a stale one, and reloading lands on the new build.
 *
 * Nothing here reloads on its own initiative: `reloadIfStale` is called when the reader has just
 * asked for something (opened a scene, the practice or the guide) that could not be loaded.
 */

let replaced = false;

/** Called when a newer build's service worker has taken over this page. */
export function markBuildReplaced(): void {
  replaced = true;
}

/** Whether a newer build has taken over this page (see markBuildReplaced). */
export function buildReplaced(): boolean {
  return replaced;
}

/** The module scripts a page of this build starts with (their names carry the build's hashes). */
export function entryScripts(doc: Pick<Document, 'querySelectorAll'>): string[] {
  return [...doc.querySelectorAll<HTMLScriptElement>('script[type="module"][src]')]
    .map((s) => s.getAttribute('src') ?? '')
    .sort();
}

/**
 * Whether the site now serves another build than this page's: the served index.html (through the
 * service worker when one controls the page) starts other entry scripts. Unreachable: false.
 */
export async function newerBuildServed(): Promise<boolean> {
  if (replaced) return true;
  try {
    const res = await fetch(new URL('index.html', document.baseURI).href, { cache: 'no-store' });
    if (!res.ok) return false;
    const served = new DOMParser().parseFromString(await res.text(), 'text/html');
    const mine = entryScripts(document);
    const theirs = entryScripts(served);
    return mine.length > 0 && theirs.length > 0 && mine.join('\n') !== theirs.join('\n');
  } catch {
    return false;
  }
}

const GUARD = 'rml:stale-reload';
/** How long a reload of one address stays the last one tried. */
const GUARD_MS = 60_000;

/**
 * After a chunk failed to load: reload (true) or say so (false)? Reload only when a newer build
 * is served, and not when this address was reloaded for the same reason less than a minute ago
 * (`guard`: what the last reload left in session storage, unreadable as none), so a build that
 * cannot load a chunk at all shows its error instead of reloading in a loop.
 */
export function shouldReload(newer: boolean, guard: string | null, here: string, now: number): boolean {
  if (!newer) return false;
  let last: unknown = null;
  try {
    last = JSON.parse(guard ?? 'null');
  } catch {
    last = null;
  }
  if (!last || typeof last !== 'object') return true;
  const { href, at } = last as { href?: unknown; at?: unknown };
  return !(href === here && typeof at === 'number' && now - at < GUARD_MS);
}

/**
 * After a failed chunk load: if a newer build is served, reload the page (it keeps its URL, so the
 * reader lands where they were going, on the new build) and resolve true; see shouldReload.
 */
export async function reloadIfStale(): Promise<boolean> {
  const newer = await newerBuildServed();
  const here = window.location.href;
  let guard: string | null = null;
  try {
    guard = sessionStorage.getItem(GUARD);
  } catch {
    /* no session storage (sandboxed): reload once anyway; a second failure finds `replaced` unchanged */
  }
  if (!shouldReload(newer, guard, here, Date.now())) return false;
  try {
    sessionStorage.setItem(GUARD, JSON.stringify({ href: here, at: Date.now() }));
  } catch {
    /* as above */
  }
  window.location.reload();
  return true;
}

/**
 * `import()` of a lazy chunk that, if it fails on a page of a replaced build, reloads the page onto
 * the new build instead of failing (the returned promise then never settles); other failures reject
 * as before.
 */
export function importOrReload<T>(load: () => Promise<T>): Promise<T> {
  return load().catch(async (err: unknown) => {
    if (await reloadIfStale()) return new Promise<T>(() => undefined);
    throw err;
  });
}
