/**
 * A storm of seed changes through every way a scene's address changes: a typed hash, a pasted link
 * (a full URL), the history's back and forward, and a host page's `set` (the host API, over
 * postMessage). The scene runs in a frame of a host page that fills the viewport. Shared by
 * scripts/perf-longtasks.mjs (how long the main thread's tasks take meanwhile) and the browser
 * test tests/e2e/address-storm.spec.ts (the last change wins).
 */

/** Where the host page is served: the browser context answers it (page.route), on the app's origin. */
export const HOST_PATH = '/storm-host.html';

/** The host page: the app at `src` (a URL, or a path on the same origin) in a frame filling the viewport. */
export function hostPage(src: string): string {
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Storm host</title>
<style>html,body{margin:0;height:100%}iframe{display:block;border:0;width:100%;height:100%}</style>
</head><body><iframe id="scene" title="Scene" src="${src}"></iframe></body></html>`;
}

export interface StormArgs {
  /** The scene's hash without a seed, e.g. '#/hemisphere?n=200000'. */
  hash: string;
  /** How many changes. */
  n: number;
}

/**
 * Runs in the host page (page.evaluate): `n` seed changes of the framed scene, taking turns
 * through the five ways (a typed hash, a pasted link, back, forward, the host's `set`). Each change
 * waits until the scene has it (its hashchange, or the reply to the `set`) and one animation frame
 * more, as a quick reader would. Resolves to the seed of the last change. Self-contained (it is
 * serialised into the page).
 */
export async function addressStorm({ hash, n }: StormArgs): Promise<number> {
  const frame = document.getElementById('scene') as HTMLIFrameElement;
  const win = frame.contentWindow!;
  const sep = hash.includes('?') ? '&' : '?';
  const at = (seed: number) => `${hash}${sep}seed=${seed}`;
  const hashchange = () =>
    new Promise<void>((r) => win.addEventListener('hashchange', () => r(), { once: true }));
  const reply = (id: number) =>
    new Promise<void>((r) => {
      const on = (e: MessageEvent) => {
        if ((e.data as { id?: unknown } | null)?.id !== id) return;
        window.removeEventListener('message', on);
        r();
      };
      window.addEventListener('message', on);
    });
  // the seeds of the history entries behind the current one, for back and forward
  const behind: number[] = [];
  let seed = 1;
  let ahead = 0;
  for (let i = 0; i < n; i++) {
    const way = i % 5;
    const taken = way === 4 ? reply(i) : hashchange();
    if (way === 0 || way === 1) {
      behind.push(seed);
      seed += 1;
      if (way === 0) win.location.hash = at(seed);
      else win.location.href = new URL(at(seed), win.location.href).href;
    } else if (way === 2) {
      ahead = seed;
      seed = behind.pop()!;
      win.history.back();
    } else if (way === 3) {
      behind.push(seed);
      seed = ahead;
      win.history.forward();
    } else {
      // the host's set replaces the current entry's seed (the scene rewrites its URL in place)
      seed += 1;
      win.postMessage({ protocol: 'render-math-lab', version: 1, id: i, type: 'set', params: { seed } }, '*');
    }
    await taken;
    await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
  }
  return seed;
}
