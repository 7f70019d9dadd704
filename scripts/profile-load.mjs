#!/usr/bin/env node
/**
 * Where the main thread spends a scene's first seconds: a CPU profile (CDP Profiler, 4x CPU
 * throttling, phone-sized viewport) of loading a route of the built app, aggregated by function
 * (self time) and by script, plus the long tasks (> 50 ms) seen by a PerformanceObserver. A
 * diagnostic for Lighthouse TBT, not a test.
 *
 *   node scripts/profile-load.mjs [--dist dist] [--port 4336] [--ms 8000] [--top 25] [--rate 4] '#/hemisphere' …
 */
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, findChromium } from './chromium.mjs';
import { inclusive, printTop, serveDist, summarize, takeOpt, PHONE_CONTEXT } from './cpuprofile.mjs';

const args = process.argv.slice(2);
const opt = (n, d) => takeOpt(args, n, d);
const dist = opt('--dist', 'dist');
const port = Number(opt('--port', '4336'));
const ms = Number(opt('--ms', '8000'));
const top = Number(opt('--top', '25'));
// CPU slowdown (1 = none: then each busy stretch is about one task, as in Lighthouse's unthrottled trace)
const rate = Number(opt('--rate', '4'));
const routes = args.length ? args : ['#/hemisphere'];

const server = await serveDist(dist, port);
const browser = await chromium.launch({ executablePath: findChromium(), args: CHROMIUM_ARGS });
try {
  for (const route of routes) {
    const ctx = await browser.newContext(PHONE_CONTEXT);
    const page = await ctx.newPage();
    const cdp = await ctx.newCDPSession(page);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate });
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
    const s = summarize(profile, { top });
    const sum = (a) => a.reduce((acc, x) => acc + x[1], 0);
    console.log(
      `\n== ${route}  (${((Date.now() - t0) / 1000).toFixed(1)} s wall, busy ${s.total.toFixed(0)} ms, long tasks ${long.length}: ${sum(long)} ms, TBT-like ${long.reduce((acc, x) => acc + Math.max(0, x[1] - 50), 0)} ms)`,
    );
    console.log('long tasks [start, ms]:', JSON.stringify(long));
    s.print();
    // the longest busy stretches (no idle sample for > GAP_MS, default 30 ms: CPU throttling itself
    // shows as idle samples): what ran in each, by inclusive time
    const stretches = [];
    const GAP_US = Number(process.env.GAP_MS ?? 30) * 1000;
    let cur = null;
    let clock = profile.startTime;
    for (let i = 0; i < profile.samples.length; i++) {
      clock += profile.timeDeltas[i];
      if (s.ix.nodes.get(profile.samples[i]).callFrame.functionName === '(idle)') continue;
      if (!cur || clock - cur.end > GAP_US) {
        cur = { start: clock, end: clock, samples: [] };
        stretches.push(cur);
      }
      cur.end = clock;
      cur.samples.push(s.ix.samples[i]);
    }
    stretches.sort((a, b) => b.end - b.start - (a.end - a.start));
    for (const st of stretches.slice(0, Number(process.env.STRETCHES ?? 4))) {
      printTop(
        `-- stretch at ${((st.start - profile.startTime) / 1000).toFixed(0)} ms, ${((st.end - st.start) / 1000).toFixed(0)} ms long; inclusive:`,
        inclusive(s.ix, st.samples),
        30,
      );
    }
    await ctx.close();
  }
} finally {
  await browser.close();
  server.kill();
}
