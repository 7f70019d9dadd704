#!/usr/bin/env node
/**
 * Bundle budgets for the production build (run after `npm run build`). Gzipped sizes:
 *  - the entry (what `#/` downloads: index.html's module script and stylesheet, inline in the page
 *    but counted here, plus every chunk the entry imports statically) ≤ 96.5 kB, and none of
 *    three.js, mathjs, KaTeX in it (the shell itself: routing, the scene host, the share
 *    bar, the link's shell flags with the folds it opens, the deck's slide host, and the shared
 *    components' styles; every page's own code is a lazy chunk);
 *  - each heavy library and each scene chunk under its own ceiling;
 *  - what the practice index (`#/practice`) and each question page download beyond the entry
 *    under their own ceilings;
 *  - the script files each route asks for before its first paint under a ceiling;
 *  - the single-file copy (dist-single/index.html, when built) under its own ceiling.
 * Exits 1 and says which budget broke.
 */
import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { join } from 'node:path';
import { readPreloadMap } from './preloadMap.mjs';

const dist = process.argv[2] ?? 'dist';
if (!existsSync(join(dist, 'index.html'))) {
  console.error(`budgets: no ${dist}/index.html; run "npm run build" first`);
  process.exit(1);
}
const kB = (n) => (n / 1000).toFixed(1);
const gz = (file) => gzipSync(readFileSync(join(dist, file)), { level: 9 }).length;

const html = readFileSync(join(dist, 'index.html'), 'utf8');
const roots = [
  ...html.matchAll(/<(?:script|link)[^>]+(?:src|href)="\.?\/?(assets\/[^"]+\.(?:js|css))"/g),
].map((m) => m[1]);

// Follow static imports (not dynamic import()) from the entry scripts.
const entryFiles = new Set();
const queue = [...roots];
while (queue.length) {
  const f = queue.shift();
  if (entryFiles.has(f)) continue;
  entryFiles.add(f);
  if (!f.endsWith('.js')) continue;
  const src = readFileSync(join(dist, f), 'utf8');
  for (const m of src.matchAll(/(?:^|[;\n}])\s*import\s*(?:[\w*${}\s,]+from\s*)?["'](\.\/[^"']+\.js)["']/g)) {
    queue.push(`assets/${m[1].slice(2)}`);
  }
  for (const m of src.matchAll(/\bfrom\s*["'](\.\/[^"']+\.js)["']/g)) queue.push(`assets/${m[1].slice(2)}`);
}

const failures = [];
// Libraries recognised by strings their minified code keeps, wherever they end up.
const SIGNATURES = [
  ['three.js', /THREE\.WebGLRenderer|three\.module/],
  ['KaTeX', /KaTeX parse error/],
  ['mathjs', /typed-function|Unexpected end of expression|Undefined symbol/],
];
let entryTotal = 0;
const rows = [];
for (const f of entryFiles) {
  const s = gz(f);
  entryTotal += s;
  rows.push(['entry', f, s]);
  if (/vendor-(three|mathjs|katex)/.test(f)) failures.push(`the entry pulls in ${f}`);
  if (f.endsWith('.js')) {
    const src = readFileSync(join(dist, f), 'utf8');
    for (const [lib, re] of SIGNATURES)
      if (re.test(src)) failures.push(`the entry chunk ${f} contains ${lib}`);
  }
}
// Includes about 1 kB of rolldown's registry and per-module wrappers for shared chunks inlined into
// their readers (vite.config.ts), which buy a scene 8–10 script requests before its first paint
// instead of 19–28.
const ENTRY_LIMIT = 96_500;
if (entryTotal > ENTRY_LIMIT)
  failures.push(`entry is ${kB(entryTotal)} kB gzipped, over ${kB(ENTRY_LIMIT)} kB`);

const LIMITS = [
  [/^vendor-three-/, 200_000],
  [/^draw-/, 12_000], // the plots' chart (src/ui/chart/draw.ts), loaded with a page's first plot
  [/^vendor-katex-/, 110_000],
  [/^katex\.worker-/, 110_000], // KaTeX typesets in a worker (src/ui/katex.worker.ts)
  [/^katex-.*\.css$/, 20_000],
  [/^scene-/, 150_000],
  [/^PracticeRoute-/, 60_000], // practice mode (src/practice), its own lazy chunk
];
for (const f of readdirSync(join(dist, 'assets'))) {
  const rel = `assets/${f}`;
  if (entryFiles.has(rel)) continue;
  if (!/\.(js|css)$/.test(f)) continue;
  const s = gz(rel);
  const lim = LIMITS.find(([re]) => re.test(f));
  rows.push([lim ? 'lazy (budget)' : 'lazy', rel, s, lim?.[1]]);
  if (lim && s > lim[1]) failures.push(`${rel} is ${kB(s)} kB gzipped, over its ${kB(lim[1])} kB budget`);
}

// What a route downloads beyond the entry, from the route preload map index.html carries
// (scripts/routePreload.ts): the practice index lists the questions without their generators and
// the marking code, which load with a question page; a question page loads its own question's
// generator, not the other five's.
const ROUTE_LIMITS = [
  ['practice', 20_000],
  // the class results page: the page and its drop zone; the answer checker loads in its worker
  ['results', 20_000],
  ...['q1', 'q2', 'q3', 'q4', 'q5', 'q6'].map((q) => [`practice/${q}`, 50_000]),
];
const preloadMap = readPreloadMap(html);
for (const [route, limit] of ROUTE_LIMITS) {
  const files = preloadMap?.[route];
  if (!files) {
    failures.push(`index.html has no preload list for #/${route}`);
    continue;
  }
  const s = [...files.js, ...files.css].reduce((sum, f) => sum + gz(f), 0);
  rows.push(['route', `#/${route} (${files.js.length + files.css.length} files)`, s, limit]);
  if (s > limit)
    failures.push(`#/${route} downloads ${kB(s)} kB gzipped beyond the entry, over ${kB(limit)} kB`);
}

// Script files each route asks for before its first paint: the entry's and those the preload map
// lists for the route. Each is a request, and a phone fetches them a few at a time, in rounds of
// round trips (vite.config.ts copies small shared chunks into their readers to keep this low). The
// worksheet loads all six questions' generators for printing.
const SCRIPTS_LIMIT = 12;
const SCRIPTS_LIMIT_FOR = { 'practice/sheet': 18 };
const entryScripts = [...entryFiles].filter((f) => f.endsWith('.js')).length;
const scriptCounts = [];
for (const [route, files] of Object.entries(preloadMap ?? {})) {
  const n = entryScripts + files.js.length;
  const limit = SCRIPTS_LIMIT_FOR[route] ?? SCRIPTS_LIMIT;
  scriptCounts.push(`#/${route} ${n}`);
  if (n > limit) failures.push(`#/${route} asks for ${n} script files before its first paint, over ${limit}`);
}

// The single-file copy (npm run build:single): one HTML with everything inlined, for LMS uploads
// and USB sticks. Reported with its own ceiling; skipped (and said so) when it has not been built.
const singleFile = process.argv[3] ?? 'dist-single/index.html';
const SINGLE_LIMIT = 1_700_000; // 1.39 MB gzipped when set: room for growth, not for a library
let singleLine = `single file    (not built: run "npm run build:single" to measure ${singleFile})`;
if (existsSync(singleFile)) {
  const raw = readFileSync(singleFile);
  const g = gzipSync(raw, { level: 9 }).length;
  singleLine = `single file  ${kB(g).padStart(8)} kB  ${singleFile} (${(raw.length / 1e6).toFixed(2)} MB uncompressed; ≤ ${kB(SINGLE_LIMIT)} kB gzipped)`;
  if (g > SINGLE_LIMIT)
    failures.push(`${singleFile} is ${kB(g)} kB gzipped, over its ${kB(SINGLE_LIMIT)} kB budget`);
}

rows.sort((a, b) => (a[0] === b[0] ? b[2] - a[2] : a[0] < b[0] ? -1 : 1));
for (const [kind, f, s, lim] of rows)
  console.log(`${kind.padEnd(14)} ${kB(s).padStart(8)} kB  ${f}${lim ? `  (≤ ${kB(lim)} kB)` : ''}`);
console.log(
  `entry total    ${kB(entryTotal).padStart(8)} kB  (≤ ${kB(ENTRY_LIMIT)} kB; no three.js, mathjs or KaTeX)`,
);
console.log(
  `scripts        before first paint (≤ ${SCRIPTS_LIMIT}; the worksheet ≤ ${SCRIPTS_LIMIT_FOR['practice/sheet']}): ${scriptCounts.join(', ')}`,
);
console.log(singleLine);
if (failures.length) {
  console.error(`\nbudgets: FAILED\n  ${failures.join('\n  ')}`);
  process.exit(1);
}
console.log('budgets: 1 passed, 0 failed');
