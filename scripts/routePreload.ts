/**
 * Vite build plugin: start downloading the opened scene's chunks with the entry, not after it.
 *
 * A scene's code is a lazy chunk that the shell imports once React has rendered, so on a phone its
 * download waited for the entry's download, evaluation and first render (a chain of round trips
 * before the scene's first paint, Lighthouse's LCP). This writes into index.html a tiny inline
 * script that reads the hash route and adds `<link rel="modulepreload">` for the route's scene
 * chunk (or the practice page's, or the teacher's guide's) and every chunk it imports statically (and `<link rel="preload" as="style">` for its CSS),
 * so they download alongside the entry. When the shell then imports the scene, the browser has the
 * modules already (Vite's preload helper sees the links and does not add them again).
 *
 * The map (scene id → files) is computed from the bundle; files the entry loads anyway are left
 * out. Not used by the single-file build (everything is inline there). The hash is user input:
 * only the map's own keys are looked up, and an unknown route preloads nothing.
 */
import type { Plugin } from 'vite';

interface ChunkLike {
  type: 'chunk';
  fileName: string;
  imports: string[];
  isEntry: boolean;
  isDynamicEntry: boolean;
  facadeModuleId: string | null;
  viteMetadata?: { importedCss: Set<string> };
}
type BundleLike = Record<string, ChunkLike | { type: 'asset'; fileName: string }>;

const SCENE_ENTRY = /[\\/]src[\\/]scenes[\\/]([a-z0-9-]+)[\\/]index\.ts$/;
/**
 * The other lazily loaded routes (their chunks' entry modules): `#/practice`, `#/guide`, and the
 * practice pages loaded by the practice chunk: a question (`#/practice/q1` … `q6`, one key for
 * all six) and the worksheet.
 */
const OTHER_ROUTES: Array<[RegExp, string]> = [
  [/[\\/]src[\\/]practice[\\/]PracticeRoute\.tsx$/, 'practice'],
  [/[\\/]src[\\/]practice[\\/]QuestionRoute\.tsx$/, 'practice/question'],
  [/[\\/]src[\\/]practice[\\/]Sheet\.tsx$/, 'practice/sheet'],
  [/[\\/]src[\\/]guide[\\/]Guide\.tsx$/, 'guide'],
];

/** The route id a lazy chunk's entry module serves ('alpha' for src/scenes/alpha/index.ts), or null. */
function routeOf(facade: string | null): string | null {
  const m = SCENE_ENTRY.exec(facade ?? '');
  if (m) return m[1];
  for (const [re, id] of OTHER_ROUTES) if (re.test(facade ?? '')) return id;
  return null;
}

/**
 * Route id (a scene's id, 'practice', 'guide') → the files to preload for it (scripts, then
 * stylesheets). Exported for tests.
 */
export function scenePreloadMap(bundle: BundleLike): Record<string, { js: string[]; css: string[] }> {
  const chunk = (f: string): ChunkLike | null => {
    const c = bundle[f];
    return c && c.type === 'chunk' ? c : null;
  };
  const closure = (start: string): { js: Set<string>; css: Set<string> } => {
    const js = new Set<string>();
    const css = new Set<string>();
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
  for (const c of Object.values(bundle)) {
    if (c.type !== 'chunk' || !c.isEntry) continue;
    const cl = closure(c.fileName);
    cl.js.forEach((f) => entry.js.add(f));
    cl.css.forEach((f) => entry.css.add(f));
  }
  const out: Record<string, { js: string[]; css: string[] }> = {};
  for (const c of Object.values(bundle)) {
    if (c.type !== 'chunk' || !c.isDynamicEntry) continue;
    const id = routeOf(c.facadeModuleId);
    if (id === null) continue;
    const cl = closure(c.fileName);
    out[id] = {
      js: [...cl.js].filter((f) => !entry.js.has(f)),
      css: [...cl.css].filter((f) => !entry.css.has(f)),
    };
  }
  // a page loaded by another route's chunk (`practice/question`): what its parent brings is not
  // listed again
  for (const [id, v] of Object.entries(out)) {
    const parent = id.includes('/') ? out[id.slice(0, id.indexOf('/'))] : undefined;
    if (!parent) continue;
    v.js = v.js.filter((f) => !parent.js.includes(f));
    v.css = v.css.filter((f) => !parent.css.includes(f));
  }
  return out;
}

/**
 * The inline script (plain ES5, runs before the entry module): `map` is JSON of scenePreloadMap,
 * `base` the URL prefix of the files ('./' for a relative base). The hash's path is the key
 * (`practice/q1` … `practice/q6` all read as `practice/question`); a key `a/b` that is in the map
 * brings its parent route's files `a` too (the chunk that loads it).
 */
export function preloadScript(map: Record<string, { js: string[]; css: string[] }>, base: string): string {
  // compact form: [[js…], [css…]] per id
  const compact: Record<string, [string[], string[]]> = {};
  for (const [id, v] of Object.entries(map)) compact[id] = [v.js, v.css];
  const json = JSON.stringify(compact).replace(/</g, '\\u003c');
  return (
    `(function(){try{var m=${json},b=${JSON.stringify(base)},h=location.hash.slice(1),q=h.indexOf('?');` +
    `if(q>=0)h=h.slice(0,q);h=h.replace(/^\\/+|\\/+$/g,'').replace(/^practice\\/q[1-6]$/,'practice/question');` +
    `var o=Object.prototype.hasOwnProperty;if(!o.call(m,h))return;var k=[h],s=h.indexOf('/'),d=document.head;` +
    `if(s>0&&o.call(m,h.slice(0,s)))k.unshift(h.slice(0,s));` +
    `function a(r,f,t){var l=document.createElement('link');l.rel=r;if(t)l.as=t;l.crossOrigin='';l.href=b+f;d.appendChild(l)}` +
    `k.forEach(function(i){m[i][0].forEach(function(f){a('modulepreload',f)});m[i][1].forEach(function(f){a('preload',f,'style')})})` +
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
        // before the entry's tags (a classic script after a stylesheet link would wait for the stylesheet)
        const at = html.indexOf('<script type="module"');
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
