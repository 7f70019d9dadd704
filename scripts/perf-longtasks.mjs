#!/usr/bin/env node
/**
 * Long main-thread tasks at the largest sample counts: every scene opened with each of its count
 * parameters at the maximum its URL schema allows (every integer parameter of `src/scenes/<id>/params.ts`
 * but the seed and the timeline's t), then a storm of seed changes (200 hash changes, as fast as
 * the page takes them), plus the heaviest point set of the hemisphere at 10⁶ samples. The "mixed"
 * storm (--mixed, 40 changes) embeds the scene in a host page's frame and changes the seed through
 * every way its address changes (./addressStorm.ts: a typed hash, a pasted link, back, forward, the
 * host API's `set`), on every seeded scene at its largest counts and on #/hemisphere at n = 200 000.
 * The goal: no task over 50 ms, anywhere. A benchmark, not a test (tests/e2e/storm.spec.ts and
 * tests/e2e/address-storm.spec.ts check only that the last change of such a storm wins); writes
 * bench/longtasks.json and prints, per route, the tasks over the goal and the longest.
 *
 *   npm run perf:longtasks, or npm run build && node scripts/perf-longtasks.mjs [--dist dist] [--port 4422] [--changes 200]
 *     [--mixed 40] [--scenes hemisphere,monte-carlo] [--case mixed] [--at 0.5] [--open convergence,error]
 *     [--js] [--min 50] [--out bench/longtasks.json]
 * (--case: only the cases whose name contains the text; --at: the storms run with the page
 * scrolled to that fraction of its height, 0 = the top; --open: the folds every case opens.)
 *
 * Durations come from a Chromium trace of the page's main thread: `cpu` is the thread's own CPU
 * time inside each task (the trace's thread duration), which a machine busy with other work barely
 * inflates, `wall` is the task's wall time (what the Long Tasks API reports; on a quiet machine the
 * two agree). The verdict uses `cpu`. --js samples the JavaScript stacks and lists, for every task
 * over --min, the app's functions that took its time (a diagnostic for finding what to move).
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { chromium } from 'playwright-core';
import { runnerImport } from 'vite';
import { SCENES } from './catalogue.mjs';
import { CHROMIUM_ARGS, findChromium, NO_CHROMIUM_HELP } from './chromium.mjs';
import { serveDist, takeOpt, traceProfileSamples } from './cpuprofile.mjs';

const load = async (rel) => (await runnerImport(new URL(rel, import.meta.url).pathname)).module;
const { pageMainThread, threadEvents, topLevelTasks, startTrace, stopTrace, TASK_CATEGORIES } =
  await load('./traceTasks.ts');
const { HOST_PATH, hostPage, addressStorm } = await load('./addressStorm.ts');

const args = process.argv.slice(2);
const dist = takeOpt(args, '--dist', 'dist');
const port = Number(takeOpt(args, '--port', '4422'));
const changes = Number(takeOpt(args, '--changes', '200'));
const only = takeOpt(args, '--scenes', '');
const min = Number(takeOpt(args, '--min', '50'));
const out = takeOpt(args, '--out', 'bench/longtasks.json');
const withJs = args.includes('--js');
// with --js: how many functions the whole storm's summary lists
const jsTop = Number(takeOpt(args, '--top', '15'));
// the mixed storm: seed changes through every way the address can change (./addressStorm.ts)
const mixedChanges = Number(takeOpt(args, '--mixed', '40'));
// --case TEXT: only the cases whose name contains TEXT
const caseFilter = takeOpt(args, '--case', '');
// --at F: the storms run with the page scrolled to F of its height (0: the top)
const at = Number(takeOpt(args, '--at', '0'));
// --defaults: every scene at its default counts instead (what the same cases cost at the usual n)
const atDefaults = args.includes('--defaults');
// --open FOLDS: every case's address opens these folds too (open=…), so the plots in them load and,
// in view (--at), redraw on every change of a storm
const openFolds = takeOpt(args, '--open', '');

const exe = findChromium();
if (!exe) {
  console.error(NO_CHROMIUM_HELP);
  process.exit(1);
}

/** The count parameters of a scene at their maxima, read from its schema (nothing listed here by hand). */
async function maxCounts(id) {
  const module = await load(`../src/scenes/${id}/params.ts`);
  const q = [];
  for (const [name, spec] of Object.entries(module.schema))
    if (spec.kind === 'number' && spec.integer && name !== 'seed' && name !== 't')
      q.push(`${name}=${spec.max}`);
  return { query: q.join('&'), seeded: 'seed' in module.schema };
}

const cases = [];
for (const s of SCENES) {
  if (only && !only.split(',').includes(s.id)) continue;
  const { query, seeded } = await maxCounts(s.id);
  const q = [query && !atDefaults ? query : '', openFolds ? `open=${openFolds}` : ''].filter(Boolean);
  const base = `#${s.path}?${q.join('&')}`;
  cases.push({ scene: s.id, name: 'load', hash: base });
  if (seeded) {
    cases.push({ scene: s.id, name: `${changes} seed changes`, hash: base, storm: 'seed' });
    cases.push({ scene: s.id, name: `${mixedChanges} mixed changes`, hash: base, storm: 'mixed' });
  }
  if (s.id === 'hemisphere') {
    // the hemisphere's slowest point set to generate (Sobol', Owen-scrambled) at its largest n
    cases.push({ scene: s.id, name: 'load, Sobol', hash: `${base}&points=sobol` });
    // the storm as a reader meets it at n = 200 000, every section on the page mounted
    cases.push({
      scene: s.id,
      name: `${mixedChanges} mixed, n=200000`,
      hash: `#${s.path}?n=200000`,
      storm: 'mixed',
    });
  }
}
const kept = caseFilter ? cases.filter((c) => c.name.includes(caseFilter)) : cases;

const CATEGORIES = [
  ...TASK_CATEGORIES,
  'v8.execute',
  ...(withJs ? ['disabled-by-default-v8.cpu_profiler'] : []),
];

/** The page's main-thread tasks (./traceTasks.ts), with what ran inside the long ones. */
function tasksOf(events) {
  const main = pageMainThread(events, `http://127.0.0.1:${port}/`);
  if (!main) return [];
  const ev = threadEvents(events, main);
  const tasks = topLevelTasks(ev);
  // JS samples (ProfileChunk events) for --js
  const { nodes, samples } = withJs ? traceProfileSamples(events, main) : { nodes: new Map(), samples: [] };
  const label = (n) =>
    `${n.callFrame.functionName || '(anon)'} ${String(n.callFrame.url).replace(/^.*\/assets\//, '')}:${n.callFrame.lineNumber + 1}`;
  /** The JS samples between two trace times: the top `k` functions by self and by inclusive count. */
  const jsBetween = (from, to, k) => {
    const self = new Map();
    const incl = new Map();
    for (const [time, id] of samples) {
      if (time < from || time > to) continue;
      const n = nodes.get(id);
      if (!n || /^\((idle|program|root)\)$/.test(n.callFrame.functionName)) continue;
      self.set(label(n), (self.get(label(n)) ?? 0) + 1);
      const seen = new Set();
      for (let x = n; x; x = nodes.get(x.parent)) {
        if (
          !/\/assets\//.test(String(x.callFrame.url)) ||
          /\/assets\/(jsx-runtime|vendor-)/.test(x.callFrame.url)
        )
          continue;
        const key = label(x);
        if (seen.has(key)) continue;
        seen.add(key);
        incl.set(key, (incl.get(key) ?? 0) + 1);
      }
    }
    const top = (m) =>
      [...m]
        .sort((a, b) => b[1] - a[1])
        .slice(0, k)
        .map(([key, c]) => `${key} ×${c}`);
    return { self: top(self), incl: top(incl) };
  };
  for (const t of tasks) {
    if (Math.max(t.cpu, t.wall) < min) continue;
    const end = t.ts + t.wall * 1000;
    // direct script events inside: what kind of work it was
    const inside = new Map();
    for (const e of ev) {
      if (e.ts < t.ts || e.ts + e.dur > end || e.name === 'RunTask') continue;
      const d = e.args?.data ?? {};
      const k =
        e.name === 'FunctionCall'
          ? `js ${d.functionName || '(anon)'} ${String(d.url ?? '').replace(/^.*\/assets\//, '')}`
          : e.name;
      inside.set(k, (inside.get(k) ?? 0) + e.dur / 1000);
    }
    t.inside = [...inside]
      .sort((a, b) => b[1] - a[1])
      .slice(0, 5)
      .map(([k, d]) => `${k} ${d.toFixed(1)}`);
    if (withJs) Object.assign(t, jsBetween(t.ts, end, 8));
  }
  // the whole trace's JavaScript by app function: what all the tasks together cost
  if (withJs && tasks.length) tasks.js = jsBetween(tasks[0].ts, Infinity, jsTop);
  return tasks;
}

/** Resolves once 1.5 s passed without a long task (at most `maxMs`). */
const quiet = (page, maxMs) =>
  page.evaluate(
    (maxMs) =>
      new Promise((resolve) => {
        const t0 = performance.now();
        let last = t0;
        new PerformanceObserver((l) => {
          for (const e of l.getEntries()) last = Math.max(last, e.startTime + e.duration);
        }).observe({ type: 'longtask', buffered: false });
        const check = () => {
          const now = performance.now();
          if (now - last > 1500 || now - t0 > maxMs) resolve(now - t0);
          else setTimeout(check, 250);
        };
        setTimeout(check, 250);
      }),
    maxMs,
  );

const server = await serveDist(dist, port);
const browser = await chromium.launch({ executablePath: exe, args: CHROMIUM_ARGS });
const results = [];
try {
  for (const c of kept) {
    const context = await browser.newContext({
      viewport: { width: 1280, height: 900 },
      serviceWorkers: 'block',
    });
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    const cdp = await context.newCDPSession(page);
    // the mixed storm drives the scene in a frame of a host page (its `set` comes from the parent)
    const framed = c.storm === 'mixed';
    if (framed)
      await context.route(`http://127.0.0.1:${port}${HOST_PATH}`, (route) =>
        route.fulfill({ contentType: 'text/html', body: hostPage(`/app/${c.hash}`) }),
      );
    const url = framed ? `http://127.0.0.1:${port}${HOST_PATH}` : `http://127.0.0.1:${port}/app/${c.hash}`;
    if (!c.storm) await startTrace(cdp, CATEGORIES);
    await page.goto(url);
    const app = framed ? page.frameLocator('#scene') : page;
    await app.locator('main#main').waitFor({ timeout: 60_000 });
    const target = framed ? page.frames().find((f) => f.url().includes('/app/')) : page;
    const scrollThrough = async () => {
      for (let y = 1; y <= 4; y++) {
        await target.evaluate((f) => window.scrollTo(0, f * document.body.scrollHeight), y / 4);
        await quiet(target, 15_000);
      }
    };
    if (!c.storm) {
      // the load: until the page is quiet, scrolled through once so every section mounts
      await quiet(page, 30_000);
      await scrollThrough();
    } else {
      await scrollThrough();
      await target.evaluate((f) => window.scrollTo(0, f * document.body.scrollHeight), at);
      await quiet(target, 30_000);
      await startTrace(cdp, CATEGORIES);
      if (framed) await page.evaluate(addressStorm, { hash: c.hash, n: mixedChanges });
      else
        // each change once the page has taken the last (a hash change and one animation frame)
        await page.evaluate(
          async ({ hash, n, param }) => {
            const sep = hash.includes('?') ? '&' : '?';
            for (let i = 1; i <= n; i++) {
              window.location.hash = `${hash}${sep}${param}=${i + 1}`;
              await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
            }
          },
          { hash: c.hash, n: changes, param: c.storm },
        );
      await quiet(target, 60_000);
    }
    const tasks = tasksOf(await stopTrace(cdp));
    const long = tasks.filter((t) => Math.max(t.cpu, t.wall) >= min);
    const r = {
      scene: c.scene,
      case: c.name,
      hash: c.hash,
      tasks: tasks.length,
      longestCpuMs: Math.round(Math.max(0, ...tasks.map((t) => t.cpu)) * 10) / 10,
      longestWallMs: Math.round(Math.max(0, ...tasks.map((t) => t.wall)) * 10) / 10,
      overMinCpu: tasks.filter((t) => t.cpu >= min).length,
      overMinWall: tasks.filter((t) => t.wall >= min).length,
      mainThreadCpuMs: Math.round(tasks.reduce((s, t) => s + t.cpu, 0)),
      errors,
    };
    results.push(r);
    console.log(
      `${c.scene.padEnd(12)} ${c.name.padEnd(20)} longest ${String(r.longestCpuMs).padStart(6)} ms cpu / ${String(r.longestWallMs).padStart(6)} ms wall; over ${min} ms: ${r.overMinCpu} cpu, ${r.overMinWall} wall; main thread ${r.mainThreadCpuMs} ms${errors.length ? `; ${errors.length} errors: ${errors[0]}` : ''}`,
    );
    for (const t of long.sort((a, b) => b.cpu - a.cpu).slice(0, withJs ? 6 : 3)) {
      console.log(`    ${t.cpu.toFixed(1)} cpu / ${t.wall.toFixed(1)} wall: ${t.inside.join(' | ')}`);
      if (t.self) console.log(`      self: ${t.self.join(' | ')}\n      app:  ${t.incl.join(' | ')}`);
    }
    if (tasks.js)
      console.log(
        `  all tasks, by function (self):\n    ${tasks.js.self.join('\n    ')}\n  all tasks, app functions (inclusive):\n    ${tasks.js.incl.join('\n    ')}`,
      );
    await context.close();
  }
} finally {
  await browser.close();
  server.kill();
}
const worst = Math.max(0, ...results.map((r) => r.longestCpuMs));
const summary = {
  date: new Date().toISOString(),
  machine: {
    cpus: cpus().length,
    model: cpus()[0]?.model,
    loadavg: loadavg().map((x) => Math.round(x * 10) / 10),
  },
  goalMs: min,
  worstCpuMs: worst,
  met: worst < min,
  results,
};
if (!only) {
  mkdirSync('bench', { recursive: true });
  writeFileSync(out, `${JSON.stringify(summary, null, 2)}\n`);
}
// per route: how many tasks over the goal (main-thread CPU) in all its cases, and the longest
console.log('\nper route: tasks over the goal (cpu), longest (cpu / wall)');
for (const scene of [...new Set(results.map((r) => r.scene))]) {
  const rs = results.filter((r) => r.scene === scene);
  const over = rs.reduce((s, r) => s + r.overMinCpu, 0);
  const cpu = Math.max(...rs.map((r) => r.longestCpuMs));
  const wall = Math.max(...rs.map((r) => r.longestWallMs));
  console.log(
    `  #/${scene.padEnd(12)} ${String(over).padStart(3)} over ${min} ms; longest ${cpu} / ${wall} ms`,
  );
}
console.log(
  `\nworst task ${worst} ms of main-thread CPU (goal < ${min} ms): ${summary.met ? 'met' : 'NOT met'}`,
);
