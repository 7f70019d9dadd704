/**
 * Vite build plugin: start downloading the opened scene's chunks with the entry, not after it.
 *
 * A scene's code is a lazy chunk that the shell imports once React has rendered, so on a phone its
 * download waited for the entry's download, evaluation and first render (a chain of round trips
 * before the scene's first paint, Lighthouse's LCP). This writes into index.html a tiny inline
 * script that reads the hash route and adds `<link rel="modulepreload">` for the route's chunk (a
 * scene's, a practice or question page's, the guide's, …) and every chunk it imports statically
 * (and `<link rel="preload" as="style">` for its CSS), so they download alongside the entry. When the shell then imports the scene, the browser has the
 * modules already (Vite's preload helper sees the links and does not add them again).
 *
 * The map (route → files: a scene's id, `practice`, `practice/q3`, `guide`, `results`, …) is
 * computed from the bundle; files the entry loads anyway are left out. Not used by the single-file
 * build (everything is inline there). The hash is user input: only the map's own keys are looked
 * up, and an unknown route preloads nothing.
 */
import type { Plugin } from 'vite';

interface ChunkLike {
  type: 'chunk';
  fileName: string;
  imports: string[];
  isEntry: boolean;
  isDynamicEntry: boolean;
  facadeModuleId: string | null;
  /** The modules the chunk holds (a route's module may sit in a shared chunk, as a question's does). */
  moduleIds?: string[];
  viteMetadata?: { importedCss: Set<string> };
}
type BundleLike = Record<string, ChunkLike | { type: 'asset'; fileName: string }>;

const SCENE_ENTRY = /[\\/]src[\\/]scenes[\\/]([a-z0-9-]+)[\\/]index\.ts$/;

/** What a chunk says of its modules (rolldown's chunk info, and the part of it these helpers read). */
export interface ChunkModules {
  facadeModuleId?: string | null;
  moduleIds?: string[];
}

/** A chunk's entry module first, then the modules it holds. */
function moduleIdsOf(c: ChunkModules): string[] {
  return [c.facadeModuleId ?? '', ...(c.moduleIds ?? [])];
}

/**
 * The scene whose code a chunk holds ('alpha' for src/scenes/alpha/index.ts), or null: by its entry
 * module or, with entry signatures not preserved (vite.config.ts), by a module it holds. Also names
 * the scene chunks' files (vite.config.ts).
 */
export function sceneOfChunk(c: ChunkModules): string | null {
  for (const id of moduleIdsOf(c)) {
    const m = SCENE_ENTRY.exec(id);
    if (m) return m[1];
  }
  return null;
}

/**
 * The other lazily loaded routes, by a module their chunk holds (`$1` in an id is the pattern's
 * first group). `with`: the other chunks the route's page loads together with this one (a
 * practice page is loaded by the practice chunk; a question page is the question page's code and
 * its question's generator, two chunks loaded at once). A `part` is loaded only with others and is
 * no route of its own.
 */
const OTHER_ROUTES: Array<{ re: RegExp; id: string; with?: string[]; part?: boolean }> = [
  // the practice pages load the results and LMS features' slots with the practice chunk (App.tsx)
  {
    re: /[\\/]src[\\/]practice[\\/]PracticeRoute\.tsx$/,
    id: 'practice',
    with: ['practice/results-slots', 'practice/lms-slots'],
  },
  { re: /[\\/]src[\\/]results[\\/]slots\.ts$/, id: 'practice/results-slots', part: true },
  { re: /[\\/]src[\\/]lms[\\/]slots\.ts$/, id: 'practice/lms-slots', part: true },
  { re: /[\\/]src[\\/]practice[\\/]QuestionRoute\.tsx$/, id: 'practice/question', part: true },
  {
    re: /[\\/]src[\\/]practice[\\/](q[1-6])\.ts$/,
    id: 'practice/$1',
    with: ['practice', 'practice/question'],
  },
  { re: /[\\/]src[\\/]practice[\\/]Sheet\.tsx$/, id: 'practice/sheet', with: ['practice'] },
  { re: /[\\/]src[\\/]guide[\\/]Guide\.tsx$/, id: 'guide' },
  { re: /[\\/]src[\\/]app[\\/]AccessibilityPage\.tsx$/, id: 'accessibility' },
  { re: /[\\/]src[\\/]deck[\\/]DeckPage\.tsx$/, id: 'deck' },
  { re: /[\\/]src[\\/]results[\\/]ResultsRoute\.tsx$/, id: 'results' },
];

/**
 * The route a chunk serves ('alpha' for the one holding src/scenes/alpha/index.ts), or null: by its
 * entry module, or by a module it holds (a question's generator is imported by the question page
 * and by the worksheet, and may sit in a chunk shared by the two, with no entry module).
 */
function routeOf(c: ChunkLike): { id: string; with: string[]; part: boolean } | null {
  for (const id of moduleIdsOf(c)) {
    const m = SCENE_ENTRY.exec(id);
    if (m) return { id: m[1], with: [], part: false };
    for (const r of OTHER_ROUTES) {
      const g = r.re.exec(id);
      if (g) return { id: r.id.replace('$1', g[1] ?? ''), with: r.with ?? [], part: r.part ?? false };
    }
  }
  return null;
}

/**
 * Route (the hash's path without its slashes: a scene's id, 'practice', 'practice/q3', 'guide') →
 * the files to preload for it (scripts, then stylesheets): its chunks and their static imports,
 * less what the entry loads anyway. Exported for tests.
 */
export function scenePreloadMap(bundle: BundleLike): Record<string, { js: string[]; css: string[] }> {
  const chunk = (f: string): ChunkLike | null => {
    const c = bundle[f];
    return c && c.type === 'chunk' ? c : null;
  };
  const closure = (start: string, js = new Set<string>(), css = new Set<string>()) => {
    const visit = (f: string) => {
      if (js.has(f)) return;
      const c = chunk(f);
      if (!c) return;
      js.add(f);
      for (const s of c.viteMetadata?.importedCss ?? []) css.add(s);
      for (const i of c.imports) visit(i);
    };
    visit(start);
    return { js, css };
  };
  // what the entry loads by itself (its static imports and stylesheets): never preloaded again
  const entry = { js: new Set<string>(), css: new Set<string>() };
  for (const c of Object.values(bundle))
    if (c.type === 'chunk' && c.isEntry) closure(c.fileName, entry.js, entry.css);
  const routes = new Map<string, { file: string; with: string[]; part: boolean }>();
  for (const c of Object.values(bundle)) {
    if (c.type !== 'chunk' || c.isEntry) continue;
    const r = routeOf(c);
    if (r) routes.set(r.id, { file: c.fileName, with: r.with, part: r.part });
  }
  const out: Record<string, { js: string[]; css: string[] }> = {};
  for (const [id, r] of routes) {
    if (r.part) continue;
    const js = new Set<string>();
    const css = new Set<string>();
    // the chunks loaded with it first (the practice chunk before a question page's), and what
    // those are loaded with in turn
    const seen = new Set<string>([id]);
    const withAll = (ws: string[]) => {
      for (const w of ws) {
        const other = routes.get(w);
        if (!other || seen.has(w)) continue;
        seen.add(w);
        withAll(other.with);
        closure(other.file, js, css);
      }
    };
    withAll(r.with);
    closure(r.file, js, css);
    out[id] = { js: [...js].filter((f) => !entry.js.has(f)), css: [...css].filter((f) => !entry.css.has(f)) };
  }
  return out;
}

/**
 * The inline script (plain ES5, runs before the entry module): `map` is scenePreloadMap's result,
 * `base` the URL prefix of the files ('./' for a relative base). The hash's path is the key. The
 * files are written once, in a list, and each route names them by index (a question page's list
 * repeats the practice page's). scripts/preloadMap.mjs reads it back.
 *
 * The links are added in a task of their own (a timeout), not while the parser runs the script:
 * adding thirty links takes tens of milliseconds (each starts a fetch), and the entry's request,
 * which the parser has already met, would otherwise wait for the end of that parser task.
 */
export function preloadScript(map: Record<string, { js: string[]; css: string[] }>, base: string): string {
  const files: string[] = [];
  const index = new Map<string, number>();
  const at = (f: string) => {
    if (!index.has(f)) index.set(f, files.push(f) - 1);
    return index.get(f)!;
  };
  // compact form: [[js…], [css…]] per route, as indices into the file list
  const compact: Record<string, [number[], number[]]> = {};
  for (const [id, v] of Object.entries(map)) compact[id] = [v.js.map(at), v.css.map(at)];
  const json = (x: unknown) => JSON.stringify(x).replace(/</g, '\\u003c');
  return (
    `(function(){try{var f=${json(files)},m=${json(compact)},b=${JSON.stringify(base)},h=location.hash.slice(1),q=h.indexOf('?');` +
    `if(q>=0)h=h.slice(0,q);h=h.replace(/^\\/+|\\/+$/g,'');` +
    `if(!Object.prototype.hasOwnProperty.call(m,h))return;var d=document.head;` +
    `function a(r,i,t){var l=document.createElement('link');l.rel=r;if(t)l.as=t;l.crossOrigin='';l.href=b+f[i];d.appendChild(l)}` +
    `setTimeout(function(){m[h][0].forEach(function(i){a('modulepreload',i)});m[h][1].forEach(function(i){a('preload',i,'style')})},0)` +
    `}catch(x){}})();`
  );
}

export function routePreload(): Plugin {
  let base = './';
  return {
    name: 'rml:route-preload',
    apply: 'build',
    configResolved(config) {
      base = config.base === '' ? './' : config.base;
    },
    transformIndexHtml: {
      order: 'post',
      handler(html, ctx) {
        if (!ctx.bundle) return html;
        const map = scenePreloadMap(ctx.bundle as unknown as BundleLike);
        if (!Object.keys(map).length) return html;
        const tag = `<script>${preloadScript(map, base)}</script>\n    `;
        // After the entry's script and module preloads, so the entry is requested first (on a
        // phone's few connections the route's many small files would otherwise queue ahead of it),
        // and before any stylesheet link (a classic script after one waits for the stylesheet).
        const at = html.indexOf('<link rel="stylesheet"');
        return at < 0 ? html.replace('</head>', `${tag}</head>`) : html.slice(0, at) + tag + html.slice(at);
      },
    },
  };
}

/**
 * Takes vite-plugin-pwa's `<link rel="manifest">` out of index.html (list this plugin after VitePWA):
 * Chromium fetched the manifest and its icon at once, two requests beside the entry's on a phone's
 * first load; src/app/pwa.ts adds the link when it registers the service worker.
 */
export function lateManifestLink(): Plugin {
  return {
    name: 'rml:late-manifest-link',
    apply: 'build',
    enforce: 'post',
    transformIndexHtml: {
      order: 'post',
      handler(html) {
        return html.replace(/\s*<link rel="manifest"[^>]*>/, '');
      },
    },
  };
}
