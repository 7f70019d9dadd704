#!/usr/bin/env node
/**
 * Lighthouse (mobile preset) on every route of the built app, served gzipped on 127.0.0.1, in the
 * system Chromium. Several runs per route; the median of each metric goes to bench/lighthouse.json
 * and a table is printed. A benchmark, not a test: it never fails on a slow score.
 *
 *   npm run perf                         (builds, then runs this script)
 *   node scripts/perf-lighthouse.mjs [--dist dist] [--port 4335] [--runs 3]
 *        [--routes '#/,#/texture' | --routes hemisphere,area-light] [--out bench/lighthouse.json]
 *        [--shots bench/lighthouse-shots]
 *
 * Mobile preset = Lighthouse's default config: Moto G Power–sized screen, simulated slow 4G
 * (150 ms RTT, 1.6 Mbps down) and 4× CPU slowdown, applied by Lighthouse's simulator (Lantern) to a
 * trace recorded without throttling. The recorded trace still runs on this machine's CPU, so a busy
 * machine inflates TBT/TTI: the script records the load average before and after and prints it
 * beside the table. Compare runs made in the same conditions.
 *
 * Hash routes: Lighthouse navigates to the URL with its hash, which is a full page load of
 * index.html that then opens the scene. To check that the scene is what was measured, each route
 * records the URL Lighthouse ended on, the LCP element (its label and HTML snippet) and the layout
 * shifts' elements; the final screenshot of the last run of each route is saved under --shots.
 */
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync, mkdirSync, existsSync } from 'node:fs';
import { tmpdir, loadavg, cpus } from 'node:os';
import { join } from 'node:path';
import lighthouse, { defaultConfig } from 'lighthouse';
// Lighthouse's own trace gatherer, extended below (a file inside the pinned package; see TraceForNewChromium).
import TraceGatherer from 'lighthouse/core/gather/gatherers/trace.js';
import { SCENES } from './catalogue.mjs';
import { CHROMIUM_ARGS, findChromium, NO_CHROMIUM_HELP } from './chromium.mjs';

/**
 * The routes measured by default: home, every scene of the catalogue, practice and the guide. Each
 * entry is the hash Lighthouse opens (query parameters allowed: '#/texture?u=0.4').
 */
const ROUTES = ['#/', ...SCENES.map((s) => `#${s.path}`), '#/practice', '#/guide'];

const args = process.argv.slice(2);
const opt = (name, def) => {
  const i = args.indexOf(name);
  if (i < 0) return def;
  const v = args[i + 1];
  if (v === undefined || v.startsWith('--')) {
    console.error(`perf: ${name} needs a value`);
    process.exit(2);
  }
  return v;
};
const dist = opt('--dist', 'dist');
const port = Number(opt('--port', process.env.PERF_PORT ?? '4335'));
const runs = Math.max(1, Math.floor(Number(opt('--runs', '3'))) || 3);
const out = opt('--out', 'bench/lighthouse.json');
const shots = opt('--shots', 'bench/lighthouse-shots');
const routes = (() => {
  const r = opt('--routes', null);
  if (!r) return ROUTES;
  return r
    .split(',')
    .map((s) => s.trim())
    .filter(Boolean)
    .map((s) => (s.startsWith('#') ? s : s === '/' || s === 'home' ? '#/' : `#/${s.replace(/^\/+/, '')}`));
})();

if (!existsSync(join(dist, 'index.html'))) {
  console.error(`perf: no ${dist}/index.html; run "npm run build" first (npm run perf does it).`);
  process.exit(1);
}
const exe = findChromium();
if (!exe) {
  console.error(NO_CHROMIUM_HELP);
  process.exit(1);
}

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const median = (xs) => {
  const v = xs.filter((x) => typeof x === 'number' && Number.isFinite(x)).sort((a, b) => a - b);
  if (!v.length) return null;
  const h = v.length >> 1;
  return v.length % 2 ? v[h] : (v[h - 1] + v[h]) / 2;
};
const load = () => loadavg().map((x) => Math.round(x * 100) / 100);

/** Start the gzip static server (a child process, so Lighthouse's own work does not delay it). */
async function startServer() {
  const child = spawn(process.execPath, ['scripts/serve.mjs', dist, String(port), '--gzip'], {
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  let err = '';
  child.stderr.on('data', (d) => (err += d));
  await new Promise((resolve, reject) => {
    child.stdout.once('data', resolve);
    child.once('exit', (code) =>
      reject(new Error(`server exited (${code}): ${err.trim()} (is port ${port} in use? pass --port)`)),
    );
  });
  return child;
}

/** Launch a headless Chromium with a debugging port; resolves to { port, kill }. */
async function launchChromium() {
  const profile = mkdtempSync(join(tmpdir(), 'perf-lh-'));
  const child = spawn(
    exe,
    [
      ...CHROMIUM_ARGS,
      '--headless=new',
      '--remote-debugging-port=0',
      `--user-data-dir=${profile}`,
      '--no-default-browser-check',
      'about:blank',
    ],
    {
      stdio: ['ignore', 'ignore', 'pipe'],
    },
  );
  const debugPort = await new Promise((resolve, reject) => {
    let buf = '';
    const timer = setTimeout(() => reject(new Error(`Chromium did not start in 60 s:\n${buf}`)), 60_000);
    child.stderr.on('data', (d) => {
      buf += d;
      const m = /DevTools listening on ws:\/\/[^:]+:(\d+)\//.exec(buf);
      if (m) {
        clearTimeout(timer);
        resolve(Number(m[1]));
      }
    });
    child.once('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`Chromium exited (${code}):\n${buf}`));
    });
  });
  return {
    port: debugPort,
    async kill() {
      child.kill('SIGTERM');
      await Promise.race([new Promise((r) => child.once('exit', r)), sleep(5000)]);
      if (child.exitCode === null) child.kill('SIGKILL');
      // Chromium's helper processes can still be writing to the profile as the browser exits: the
      // removal may need a later try, and failing it must not cost the run that was just measured
      for (let tries = 0; ; tries++) {
        try {
          rmSync(profile, { recursive: true, force: true, maxRetries: 5, retryDelay: 200 });
          break;
        } catch (e) {
          if (tries >= 3) {
            console.error(`  (could not remove ${profile}: ${e instanceof Error ? e.message : e})`);
            break;
          }
          await sleep(1000);
        }
      }
    },
  };
}

/**
 * Lighthouse 12.2.3 (the last to run on Node 20) predates the Chromium we run: newer Chromium names
 * the PipelineReporter trace event's argument `frame_reporter` where Lighthouse's trace engine reads
 * `chrome_frame_reporter`, and the LCP-element, layout-shift and root-cause gatherers then fail
 * ("Cannot read properties of undefined (reading 'frame_sequence')"). The metrics themselves are
 * unaffected; this copies the argument to the old name so those diagnostics work too.
 */
class TraceForNewChromium extends TraceGatherer {
  getArtifact(ctx) {
    const trace = super.getArtifact(ctx);
    for (const e of trace.traceEvents) {
      if (e.name === 'PipelineReporter' && e.args?.frame_reporter && !e.args.chrome_frame_reporter)
        e.args.chrome_frame_reporter = e.args.frame_reporter;
    }
    return trace;
  }
}
const CONFIG = {
  ...defaultConfig, // the mobile preset
  settings: { ...defaultConfig.settings, onlyCategories: ['performance'] },
  artifacts: defaultConfig.artifacts.map((a) =>
    a.id === 'Trace' ? { id: 'Trace', gatherer: { implementation: TraceForNewChromium } } : a,
  ),
};

const nodeOf = (item) => item?.node ?? item?.items?.[0]?.node ?? null;
const describeNode = (n) =>
  n
    ? { label: n.nodeLabel ?? null, selector: n.selector ?? null, snippet: (n.snippet ?? '').slice(0, 200) }
    : null;

let traceRun = 0;

/** One Lighthouse run of one URL; returns the numbers and the evidence of what was measured. */
async function measure(url) {
  const chrome = await launchChromium();
  try {
    const result = await lighthouse(url, { port: chrome.port, output: 'json', logLevel: 'error' }, CONFIG);
    if (!result) throw new Error('Lighthouse returned nothing');
    const { lhr } = result;
    if (process.env.PERF_DUMP) writeFileSync(process.env.PERF_DUMP, JSON.stringify(lhr));
    // the observed trace Lighthouse simulated from (for a look at its long tasks' contents)
    // ({run} in the name: one file per run, numbered in order)
    traceRun++;
    if (process.env.PERF_TRACE && result.artifacts?.Trace)
      writeFileSync(
        process.env.PERF_TRACE.replaceAll('{run}', String(traceRun)),
        JSON.stringify(result.artifacts.Trace),
      );
    if (lhr.runtimeError) throw new Error(`${lhr.runtimeError.code}: ${lhr.runtimeError.message}`);
    const a = lhr.audits;
    const num = (id) => (typeof a[id]?.numericValue === 'number' ? a[id].numericValue : null);
    const lcpItems = a['largest-contentful-paint-element']?.details?.items ?? [];
    const lcpNode = nodeOf(lcpItems[0]?.items?.[0] ?? lcpItems[0]);
    const shifts = (a['layout-shifts']?.details?.items ?? []).map((it) => ({
      score: it.score,
      node: describeNode(nodeOf(it))?.selector ?? null,
      label: describeNode(nodeOf(it))?.label ?? null,
      causes: (it.subItems?.items ?? []).map((c) => c.cause ?? c.extra?.value ?? null).filter(Boolean),
    }));
    const diagnosticErrors = ['largest-contentful-paint-element', 'layout-shifts', 'long-tasks']
      .filter((id) => a[id]?.scoreDisplayMode === 'error')
      .map((id) => `${id}: ${a[id].errorMessage}`);
    const longTasks = (a['long-tasks']?.details?.items ?? []).slice(0, 8).map((t) => ({
      url: String(t.url ?? '').replace(/^.*\/assets\//, 'assets/'),
      startTime: Math.round(t.startTime),
      duration: Math.round(t.duration),
    }));
    const bootup = (a['bootup-time']?.details?.items ?? []).slice(0, 6).map((t) => ({
      url: String(t.url ?? '').replace(/^.*\/assets\//, 'assets/'),
      total: Math.round(t.total),
      scripting: Math.round(t.scripting),
    }));
    return {
      score: lhr.categories.performance.score,
      fcp: num('first-contentful-paint'),
      lcp: num('largest-contentful-paint'),
      tbt: num('total-blocking-time'),
      cls: num('cumulative-layout-shift'),
      tti: num('interactive'),
      si: num('speed-index'),
      bytes: num('total-byte-weight'),
      mainThreadMs: num('mainthread-work-breakdown'),
      finalUrl: lhr.finalDisplayedUrl,
      lcpElement: describeNode(lcpNode),
      layoutShifts: shifts,
      longTasks,
      bootup,
      warnings: [...(lhr.runWarnings ?? []), ...diagnosticErrors],
      screenshot: a['final-screenshot']?.details?.data ?? null,
      lighthouseVersion: lhr.lighthouseVersion,
      userAgent: lhr.environment?.hostUserAgent ?? null,
      benchmarkIndex: lhr.environment?.benchmarkIndex ?? null,
    };
  } finally {
    await chrome.kill();
  }
}

const server = await startServer();
const base = `http://127.0.0.1:${port}/app/`;
const loadAtStart = load();
console.log(
  `perf: Lighthouse mobile, ${runs} run(s) × ${routes.length} route(s) on ${base}; load average ${loadAtStart.join(', ')} (${cpus().length} CPUs)`,
);
const results = {};
let meta = {};
try {
  for (const route of routes) {
    const url = `${base}${route}`;
    const rs = [];
    for (let i = 0; i < runs; i++) {
      const t0 = Date.now();
      try {
        const r = await measure(url);
        rs.push(r);
        meta = { lighthouseVersion: r.lighthouseVersion, userAgent: r.userAgent };
        console.log(
          `  ${route} run ${i + 1}/${runs}: score ${r.score?.toFixed(2)} TBT ${Math.round(r.tbt)} ms CLS ${r.cls?.toFixed(3)} LCP ${Math.round(r.lcp)} ms (${((Date.now() - t0) / 1000).toFixed(0)} s, load ${load()[0]})`,
        );
      } catch (e) {
        console.error(`  ${route} run ${i + 1}/${runs} failed: ${e instanceof Error ? e.message : e}`);
      }
    }
    if (!rs.length) {
      results[route] = { error: 'every run failed' };
      continue;
    }
    const last = rs[rs.length - 1];
    const expected = url;
    const wrongUrl = rs.filter((r) => r.finalUrl !== expected).map((r) => r.finalUrl);
    if (wrongUrl.length)
      console.warn(`  ${route}: Lighthouse ended on ${wrongUrl.join(', ')} instead of ${expected}`);
    let shot = null;
    if (shots && last.screenshot) {
      mkdirSync(shots, { recursive: true });
      const name = (route.replace(/^#\/?/, '') || 'home').replace(/[^a-z0-9-]+/gi, '_');
      shot = join(shots, `${name}.jpg`);
      writeFileSync(shot, Buffer.from(last.screenshot.replace(/^data:image\/\w+;base64,/, ''), 'base64'));
    }
    const med = (k) => median(rs.map((r) => r[k]));
    results[route] = {
      runs: rs.length,
      median: {
        score: med('score'),
        fcp: med('fcp'),
        lcp: med('lcp'),
        tbt: med('tbt'),
        cls: med('cls'),
        tti: med('tti'),
        si: med('si'),
        bytes: med('bytes'),
        mainThreadMs: med('mainThreadMs'),
      },
      all: rs.map(
        ({
          screenshot,
          lighthouseVersion,
          userAgent,
          layoutShifts,
          longTasks,
          bootup,
          lcpElement,
          warnings,
          finalUrl,
          ...nums
        }) => nums,
      ),
      // evidence of what was measured, from the last run
      finalUrl: last.finalUrl,
      lcpElement: last.lcpElement,
      layoutShifts: last.layoutShifts,
      longTasks: last.longTasks,
      bootup: last.bootup,
      warnings: [...new Set(rs.flatMap((r) => r.warnings))],
      screenshot: shot,
    };
  }
} finally {
  server.kill();
}
const loadAtEnd = load();

const report = {
  date: new Date().toISOString(),
  tool: `lighthouse ${meta.lighthouseVersion ?? '?'} (mobile preset: simulated slow 4G, 4× CPU slowdown), gzip, 127.0.0.1`,
  browser: meta.userAgent ?? null,
  machine: {
    cpus: cpus().length,
    cpuModel: cpus()[0]?.model ?? null,
    loadAverageAtStart: loadAtStart,
    loadAverageAtEnd: loadAtEnd,
  },
  runsPerRoute: runs,
  units: {
    fcp: 'ms',
    lcp: 'ms',
    tbt: 'ms',
    cls: 'unitless',
    tti: 'ms',
    si: 'ms',
    bytes: 'bytes transferred (gzip)',
    mainThreadMs: 'ms (observed, unthrottled)',
  },
  routes: results,
};
mkdirSync(join(out, '..'), { recursive: true });
writeFileSync(out, `${JSON.stringify(report, null, 2)}\n`);

// The table
const fmtS = (ms) => (ms == null ? '—' : `${(ms / 1000).toFixed(2)} s`);
const rows = [['route', 'score', 'FCP', 'LCP', 'TBT', 'CLS', 'TTI', 'kB', 'LCP element']];
for (const [route, r] of Object.entries(results)) {
  if (!r.median) {
    rows.push([route, 'failed', '', '', '', '', '', '', '']);
    continue;
  }
  const m = r.median;
  rows.push([
    route,
    m.score == null ? '—' : m.score.toFixed(2),
    fmtS(m.fcp),
    fmtS(m.lcp),
    m.tbt == null ? '—' : `${Math.round(m.tbt)} ms`,
    m.cls == null ? '—' : m.cls.toFixed(3),
    fmtS(m.tti),
    m.bytes == null ? '—' : (m.bytes / 1000).toFixed(0),
    (r.lcpElement?.label ?? '').slice(0, 40),
  ]);
}
const widths = rows[0].map((_, j) => Math.max(...rows.map((row) => String(row[j]).length)));
console.log('');
for (const [i, row] of rows.entries()) {
  console.log(`| ${row.map((c, j) => String(c).padEnd(widths[j])).join(' | ')} |`);
  if (i === 0) console.log(`|${widths.map((w) => '-'.repeat(w + 2)).join('|')}|`);
}
console.log(
  `\nload average at start ${loadAtStart.join(', ')}, at end ${loadAtEnd.join(', ')} (${cpus().length} CPUs). Wrote ${out}${shots ? `; final screenshots in ${shots}/` : ''}.`,
);
