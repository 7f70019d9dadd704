#!/usr/bin/env node
/**
 * What Lighthouse's simulated LCP is made of: runs Lighthouse (mobile preset) once on a
 * route of a build, served gzipped on 127.0.0.1, then prints the request/task graph that Lantern
 * simulates for LCP, each node with its simulated start–end (ms), the slowest end being the LCP.
 * Network nodes: every request that ended before the observed LCP (so anything started before the
 * page's largest paint costs LCP, related or not); CPU nodes: the observed task (obs@ms, duration
 * unthrottled; simulated ×4). A diagnostic, not a test. BOTH=1 also prints the optimistic graph;
 * FCP=1 prints FCP's graph instead of LCP's.
 *
 *   node scripts/lantern-lcp.mjs [dist] ['#/hemisphere'] [port=4432] [save.json]
 *   node scripts/lantern-lcp.mjs save.json '#/hemisphere'     (re-analyse saved artifacts)
 */
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import lighthouse, { defaultConfig } from 'lighthouse';
import TraceGatherer from 'lighthouse/core/gather/gatherers/trace.js';
import { LanternLargestContentfulPaint } from 'lighthouse/core/computed/metrics/lantern-largest-contentful-paint.js';
import { LanternFirstContentfulPaint } from 'lighthouse/core/computed/metrics/lantern-first-contentful-paint.js';
import { CHROMIUM_ARGS, findChromium } from './chromium.mjs';
const [dist = 'dist', route = '#/hemisphere', portS = '4432', save = ''] = process.argv.slice(2);
const port = Number(portS);
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
let data;
if (dist.endsWith('.json')) {
  data = JSON.parse(readFileSync(dist, 'utf8'));
} else {
  const srv = spawn(process.execPath, ['scripts/serve.mjs', dist, String(port), '--gzip'], {
    stdio: ['ignore', 'pipe', 'inherit'],
  });
  await new Promise((r) => srv.stdout.once('data', r));
  const profile = mkdtempSync(join(tmpdir(), 'lan-'));
  const ch = spawn(
    findChromium(),
    [
      ...CHROMIUM_ARGS,
      '--headless=new',
      '--remote-debugging-port=0',
      `--user-data-dir=${profile}`,
      'about:blank',
    ],
    { stdio: ['ignore', 'ignore', 'pipe'] },
  );
  const dport = await new Promise((res) => {
    let b = '';
    ch.stderr.on('data', (d) => {
      b += d;
      const m = /DevTools listening on ws:\/\/[^:]+:(\d+)\//.exec(b);
      if (m) res(Number(m[1]));
    });
  });
  class T extends TraceGatherer {
    getArtifact(ctx) {
      const t = super.getArtifact(ctx);
      for (const e of t.traceEvents)
        if (e.name === 'PipelineReporter' && e.args?.frame_reporter && !e.args.chrome_frame_reporter)
          e.args.chrome_frame_reporter = e.args.frame_reporter;
      return t;
    }
  }
  const CONFIG = {
    ...defaultConfig,
    settings: { ...defaultConfig.settings, onlyCategories: ['performance'] },
    artifacts: defaultConfig.artifacts.map((a) =>
      a.id === 'Trace' ? { id: 'Trace', gatherer: { implementation: T } } : a,
    ),
  };
  const r = await lighthouse(
    `http://127.0.0.1:${port}/app/${route}`,
    { port: dport, output: 'json', logLevel: 'error' },
    CONFIG,
  );
  ch.kill();
  srv.kill();
  await sleep(300);
  rmSync(profile, { recursive: true, force: true });
  data = {
    trace: r.artifacts.Trace,
    devtoolsLog: r.artifacts.DevtoolsLog,
    gatherContext: r.artifacts.GatherContext,
    URL: r.artifacts.URL,
    settings: r.lhr.configSettings,
    lcp: r.lhr.audits['largest-contentful-paint'].numericValue,
  };
  if (save) writeFileSync(save, JSON.stringify(data));
}
const context = { computedCache: new Map(), settings: data.settings };
const md = {
  trace: data.trace,
  devtoolsLog: data.devtoolsLog,
  gatherContext: data.gatherContext,
  settings: data.settings,
  URL: data.URL,
};
const fcp = await LanternFirstContentfulPaint.request(md, context);
const res = await LanternLargestContentfulPaint.request(md, context);
console.log(
  `${route}: LCP ${Math.round(res.timing)} (opt ${Math.round(res.optimisticEstimate.timeInMs)}, pess ${Math.round(res.pessimisticEstimate.timeInMs)}), FCP ${Math.round(fcp.timing)}`,
);
const short = (u) => String(u).replace(/^.*\/app\//, '');
for (const which of process.env.BOTH ? ['optimistic', 'pessimistic'] : ['pessimistic']) {
  const est = (process.env.FCP ? fcp : res)[`${which}Estimate`];
  const rows = [...est.nodeTimings.entries()].sort((a, b) => a[1].startTime - b[1].startTime);
  console.log(`-- ${which}: ${rows.length} nodes`);
  for (const [n, t] of rows) {
    let what;
    if (n.type === 'network')
      what = `NET ${n.request.resourceType} ${short(n.request.url)} ${n.request.transferSize}B`;
    else {
      const evs = n.childEvents;
      const names = new Map();
      for (const e of evs) names.set(e.name, (names.get(e.name) ?? 0) + 1);
      const urls = [...n.getEvaluateScriptURLs()].map(short);
      const fc = evs
        .filter((e) => e.name === 'FunctionCall')
        .map((e) => short(e.args.data?.url ?? '') + ':' + (e.args.data?.functionName ?? ''))
        .slice(0, 3);
      what = `CPU obs@${Math.round((n.startTime - rows[0][0].startTime) / 1000)} ${Math.round(n.duration / 1000)}ms ${urls.length ? 'eval ' + urls.join(',') : ''} ${n.didPerformLayout() ? 'LAYOUT ' : ''}${evs.some((e) => e.name === 'Paint') ? 'PAINT ' : ''}${fc.join(' ')} [${[...names.keys()].filter((k) => /Layout|Paint|Parse|Evaluate|RunMicro|Timer|Animation|Message|Compile|Style/.test(k)).join(',')}]`;
    }
    console.log(
      `${String(Math.round(t.startTime)).padStart(5)}-${String(Math.round(t.endTime)).padEnd(5)} ${what}`,
    );
  }
}
process.exit(0);
