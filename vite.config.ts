import { fileURLToPath } from 'node:url';
import { defineConfig, type Plugin } from 'vite';
import react from '@vitejs/plugin-react';
import { VitePWA } from 'vite-plugin-pwa';
import { viteSingleFile } from 'vite-plugin-singlefile';
import { lateManifestLink, routePreload, sceneOfChunk, type ChunkModules } from './scripts/routePreload';
import { inlineEntryCss } from './scripts/inlineEntryCss';
import { katexCssSplit } from './scripts/katexCss';
import { appFiles } from './scripts/appFiles';
import { contentSecurityPolicy } from './scripts/csp';

/**
 * `--mode single` (npm run build:single): one self-contained HTML file. Workers are written as
 * `new Worker(new URL('./x.worker.ts', import.meta.url), { type: 'module' })` everywhere; in this
 * mode that expression becomes Vite's inlined worker (`./x.worker.ts?worker&inline`, a Blob URL),
 * so they run from file:// too.
 */
function inlineWorkers(): Plugin {
  const re =
    /new Worker\(\s*new URL\(\s*(['"])([^'"]+)\1\s*,\s*import\.meta\.url\s*\)\s*(?:,\s*\{[^{}]*\}\s*)?\)/g;
  return {
    name: 'rml:inline-workers',
    enforce: 'pre',
    transform(code, id) {
      if (!/[\\/]src[\\/].*\.tsx?$/.test(id) || !code.includes('new Worker(')) return null;
      const imports: string[] = [];
      const out = code.replace(re, (_m, _q, spec: string) => {
        const name = `__rmlInlineWorker${imports.length}`;
        imports.push(`import ${name} from ${JSON.stringify(`${spec}?worker&inline`)};`);
        return `new ${name}()`;
      });
      return imports.length ? { code: `${imports.join('\n')}\n${out}`, map: null } : null;
    },
  };
}

/**
 * @stdlib's packages are CommonJS without a `sideEffects` field, so a bundler keeps them (and runs
 * their module code, tens of ms on a phone) in every chunk that imports them, even unused: the
 * χ² test's gammainc ended up in the hemisphere page's chunk, though only its worker runs the test
 *. They have no side effects on import.
 */
const treeshake = {
  moduleSideEffects: [
    { test: /[\\/]node_modules[\\/]@stdlib[\\/]/, sideEffects: false },
    // The app's re-export modules (the views' door to the formatter, the core's barrels): with side
    // effects assumed, each kept every module it re-exports in the graph of whatever imported one
    // name from it, and some became chunks of their own that only import others (one more request
    // each before a page's first paint).
    {
      test: /[\\/]src[\\/](ui[\\/]format|core[\\/](estimators|geometry|lights|random|sampling|texture|verify)[\\/]index)\.ts$/,
      sideEffects: false,
    },
  ],
};

// Relative base: the static build works from any folder of any static host (hash routing).
export default defineConfig(({ mode }) => {
  const single = mode === 'single';
  return {
    base: './',
    plugins: single
      ? [
          react(),
          katexCssSplit(),
          inlineWorkers(),
          viteSingleFile({ removeViteModuleLoader: true }),
          contentSecurityPolicy(),
        ]
      : [
          react(),
          // KaTeX's @font-face rules in the shell's stylesheet, its other rules loaded with the formulas
          katexCssSplit(),
          // index.html starts the opened scene's chunks downloading with the entry
          routePreload(),
          // the shell's stylesheet inline in index.html: one request fewer before a page's first paint
          inlineEntryCss(),
          // Offline: a Workbox service worker precaches every file of the build (all chunks, workers,
          // fonts), so after one visit every scene opens with no network. 'prompt': a new build waits
          // until the reader accepts the "updated, reload" notice (src/app/pwa.ts), so a page never runs
          // a mix of old and new chunks.
          VitePWA({
            registerType: 'prompt',
            injectRegister: false,
            includeAssets: [],
            manifest: {
              name: 'Render Math Lab',
              short_name: 'Math Lab',
              description:
                'Interactive explorables for the mathematics of rendering, computed live in the browser.',
              start_url: './',
              scope: './',
              display: 'standalone',
              background_color: '#f7f6f2',
              theme_color: '#1c1d21',
              icons: [
                { src: 'icon-192.png', sizes: '192x192', type: 'image/png' },
                { src: 'icon-512.png', sizes: '512x512', type: 'image/png' },
                { src: 'icon-maskable-512.png', sizes: '512x512', type: 'image/png', purpose: 'maskable' },
              ],
            },
            workbox: {
              // KaTeX's fonts are declared as woff2 only (scripts/katexCss.ts); a file of another
              // kind found in the build is not precached
              globPatterns: ['**/*.{js,css,html,png,svg,ico,webmanifest,woff2,wasm,json}'],
              maximumFileSizeToCacheInBytes: 20 * 1024 * 1024,
              cleanupOutdatedCaches: true,
              clientsClaim: true,
              navigateFallback: 'index.html',
            },
          }),
          // after VitePWA: its manifest link leaves index.html; src/app/pwa.ts adds it later
          lateManifestLink(),
          // app-files.json: what the practice sheet page packs into LMS zips in the browser
          appFiles(),
          // the Content-Security-Policy meta, with the hashes of the final index.html's inline scripts
          contentSecurityPolicy(),
        ],
    build: {
      target: 'es2022',
      sourcemap: false,
      chunkSizeWarningLimit: 5000,
      // fonts stay files (KaTeX's smallest would be inlined as data: in the stylesheet that declares
      // it, the shell's, which index.html carries: bytes every page pays for a font few use); the
      // single-file build inlines everything (its plugin's own setting)
      ...(single
        ? {}
        : { assetsInlineLimit: (file: string) => (file.endsWith('.woff2') ? false : undefined) }),
      outDir: single ? 'dist-single' : 'dist',
      rolldownOptions: single
        ? { treeshake }
        : {
            treeshake,
            // inlining common chunks needs it: the entries' unused exports may be dropped (the
            // entry is index.html's script, which nothing imports)
            preserveEntrySignatures: false,
            output: {
              // three.js, Plotly and KaTeX get recognisable chunk names (vendor-three-*.js, …) for the
              // budgets. mathjs is left to the default splitting on purpose: the parse-only expression
              // engine (src/core/expr) loads only what it needs.
              // Each scene's lazy chunk is named after it (scene-texture-*.js, …); naming only, it does
              // not change how modules are split.
              chunkFileNames: (chunk: ChunkModules) => {
                const scene = sceneOfChunk(chunk);
                return scene ? `assets/scene-${scene}-[hash].js` : 'assets/[name]-[hash].js';
              },
              codeSplitting: {
                // Small shared chunks are copied into the chunks that read them instead of being
                // files of their own; a registry in rolldown's runtime keeps one instance of each
                // module (its state, its exports) across the copies (rolldown.rs, "Inline Common
                // Chunks"). Without it the default splitting gives most of the math core's 0–4 kB
                // modules a file of their own, and a scene asks for 19–28 scripts before its first
                // paint, fetched in rounds over a phone's connections. Stylesheets' modules stay out
                // (Vite emits a style module's CSS from every chunk that lists it). The size is the
                // chunk's source before minification.
                experimentalInlineCommonChunks: { maxSize: 32 * 1024, exclude: /\.css(\?|$)/ },
                groups: [
                  { name: 'vendor-three', test: /[\\/]node_modules[\\/]three[\\/]/ },
                  // KaTeX's JavaScript only: its stylesheet's module must not pull the typesetter into
                  // the page (KaTeX runs in a worker, src/ui/katex.worker.ts)
                  { name: 'vendor-katex', test: /[\\/]node_modules[\\/]katex[\\/].*\.m?js$/ },
                ],
              },
            },
          },
    },
    // single: each inlined worker is one self-contained classic script (its lazy imports folded in):
    // a page opened from file:// has an opaque origin, and Chromium refuses module workers from its
    // Blob URLs, but runs classic ones.
    worker: single
      ? { format: 'iife' as const, rolldownOptions: { output: { codeSplitting: false } } }
      : { format: 'es' as const },
    publicDir: single ? false : 'public',
    // @stdlib's generator probe evaluates a string, which the CSP refuses (scripts/stubs/)
    resolve: {
      alias: [
        {
          find: /^@stdlib\/assert-has-generator-support$/,
          replacement: fileURLToPath(new URL('./scripts/stubs/hasGeneratorSupport.cjs', import.meta.url)),
        },
      ],
    },
    server: { host: '127.0.0.1' },
  };
});
