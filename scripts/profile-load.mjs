#!/usr/bin/env node
/**
 * Where the main thread spends a scene's first seconds: a CPU profile (CDP Profiler, 4x CPU
 * throttling, phone-sized viewport) of loading a route of the built app, aggregated by function
 * (self time) and by script, plus the long tasks (> 50 ms) seen by a PerformanceObserver. A
 * diagnostic for issue 15 (Lighthouse TBT), not a test.
 *
 *   node scripts/profile-load.mjs [--dist dist] [--port 4336] [--ms 8000] [--top 25] '#/hemisphere' …
 */
import { spawn } from 'node:child_process';
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, findChromium } from './chromium.mjs';

const args = process.argv.slice(2);
const opt = (n, d) => {
  const i = args.indexOf(n);
  if (i < 0) return d;
  const v = args[i + 1];
  args.splice(i, 2);
  return v;
};
const dist = opt('--dist', 'dist');
const port = Number(opt('--port', '4336'));
const ms = Number(opt('--ms', '8000'));
const top = Number(opt('--top', '25'));
const routes = args.length ? args : ['#/hemisphere'];

const server = spawn(process.execPath, ['scripts/serve.mjs', dist, String(port)], { stdio: 'ignore' });
await new Promise((r) => setTimeout(r, 600));
const browser = await chromium.launch({ executablePath: findChromium(), args: CHROMIUM_ARGS });
try {
  for (const route of routes) {
    const ctx = await browser.newContext({ viewport: { width: 412, height: 823 }, deviceScaleFactor: 1.75, isMobile: true, hasTouch: true, serviceWorkers: 'block' });
    const page = await ctx.newPage();
    const cdp = await ctx.newCDPSession(page);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: 4 });
    await cdp.send('Profiler.enable');
    await cdp.send('Profiler.setSamplingInterval', { interval: 200 });
    await page.addInitScript(() => {
      const w = window;
      w.__long = [];
      new PerformanceObserver((l) => {
        for (const e of l.getEntries()) w.__long.push([Math.round(e.startTime), Math.round(e.duration)]);
      }).observe({ type: 'longtask', buffered: true });
    });
    await cdp.send('Profiler.start');
    const t0 = Date.now();
    await page.goto(`http://127.0.0.1:${port}/app/${route}`);
    await page.waitForTimeout(ms);
    const { profile } = await cdp.send('Profiler.stop');
    const long = await page.evaluate(() => window.__long);
    const byFn = new Map();
    const byUrl = new Map();
    const nodes = new Map(profile.nodes.map((n) => [n.id, n]));
    const dt = new Map();
    for (let i = 0; i < profile.samples.length; i++) {
      const id = profile.samples[i];
      dt.set(id, (dt.get(id) ?? 0) + (profile.timeDeltas[i + 1] ?? 0) / 1000);
    }
    let total = 0;
    for (const [id, t] of dt) {
      const n = nodes.get(id);
      const cf = n.callFrame;
      if (cf.functionName === '(idle)' || cf.functionName === '(program)') continue;
      total += t;
      const url = cf.url.replace(/^.*\/app\//, '');
      const k = `${cf.functionName || '(anon)'}  ${url}:${cf.lineNumber + 1}:${cf.columnNumber + 1}`;
      byFn.set(k, (byFn.get(k) ?? 0) + t);
      byUrl.set(url || cf.functionName, (byUrl.get(url || cf.functionName) ?? 0) + t);
    }
    const sum = (a) => a.reduce((s, x) => s + x[1], 0);
    console.log(`\n== ${route}  (${((Date.now() - t0) / 1000).toFixed(1)} s wall, busy ${total.toFixed(0)} ms, long tasks ${long.length}: ${sum(long)} ms, TBT-like ${long.reduce((s, x) => s + Math.max(0, x[1] - 50), 0)} ms)`);
    console.log('long tasks [start, ms]:', JSON.stringify(long));
    console.log('-- by script');
    for (const [k, v] of [...byUrl].sort((a, b) => b[1] - a[1]).slice(0, 12)) console.log(`${v.toFixed(0).padStart(7)} ms  ${k}`);
    console.log('-- by function (self)');
    for (const [k, v] of [...byFn].sort((a, b) => b[1] - a[1]).slice(0, top)) console.log(`${v.toFixed(0).padStart(7)} ms  ${k}`);
    // the longest busy stretches (no idle sample for > GAP_MS, default 30 ms: CPU throttling itself shows as idle samples): what ran in each, by inclusive time
    const parent = new Map();
    for (const n of profile.nodes) for (const c of n.children ?? []) parent.set(c, n.id);
    const stretches = [];
    const GAP_US = Number(process.env.GAP_MS ?? 30) * 1000;
    let cur = null;
    let clock = profile.startTime;
    for (let i = 0; i < profile.samples.length; i++) {
      clock += profile.timeDeltas[i];
      const n = nodes.get(profile.samples[i]);
      const idle = n.callFrame.functionName === '(idle)';
      if (!idle) {
        if (!cur || clock - cur.end > GAP_US) {
          cur = { start: clock, end: clock, samples: [] };
          stretches.push(cur);
        }
        cur.end = clock;
        cur.samples.push([profile.samples[i], (profile.timeDeltas[i + 1] ?? 0) / 1000]);
      }
    }
    stretches.sort((a, b) => b.end - b.start - (a.end - a.start));
    for (const st of stretches.slice(0, Number(process.env.STRETCHES ?? 4))) {
      const incl = new Map();
      for (const [id, t] of st.samples) {
        const seen = new Set();
        for (let x = id; x !== undefined; x = parent.get(x)) {
          const cf = nodes.get(x).callFrame;
          if (!cf.url.includes('/assets/')) continue;
          const k = `${cf.functionName || '(anon)'}  ${cf.url.replace(/^.*\/assets\//, '')}:${cf.lineNumber + 1}`;
          if (seen.has(k)) continue;
          seen.add(k);
          incl.set(k, (incl.get(k) ?? 0) + t);
        }
      }
      console.log(`-- stretch at ${((st.start - profile.startTime) / 1000).toFixed(0)} ms, ${((st.end - st.start) / 1000).toFixed(0)} ms long; inclusive:`);
      for (const [k, v] of [...incl].sort((a, b) => b[1] - a[1]).slice(0, 30)) console.log(`${v.toFixed(0).padStart(7)} ms  ${k}`);
    }
    await ctx.close();
  }
} finally {
  await browser.close();
  server.kill();
}
