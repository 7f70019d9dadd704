#!/usr/bin/env node
/**
 * The long main-thread tasks of a route's load, as Lighthouse sees them: a Chromium trace without
 * CPU throttling (Lighthouse's simulator multiplies each task by 4, so a task over 12.5 ms here is
 * a "long task" there), each task listed with what ran inside it (script by function, style,
 * layout, paint, HTML parsing). A diagnostic for issue 15, not a test.
 *
 *   node scripts/trace-load.mjs [--dist dist] [--port 4338] [--ms 8000] [--min 12.5] '#/texture' …
 */
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, findChromium } from './chromium.mjs';
import { serveDist, takeOpt } from './cpuprofile.mjs';

const args = process.argv.slice(2);
const opt = (n, d) => takeOpt(args, n, d);
const dist = opt('--dist', 'dist');
const port = Number(opt('--port', '4338'));
const ms = Number(opt('--ms', '8000'));
const min = Number(opt('--min', '12.5'));
const routes = args.length ? args : ['#/hemisphere'];

const server = await serveDist(dist, port);
const browser = await chromium.launch({ executablePath: findChromium(), args: CHROMIUM_ARGS });
try {
  for (const route of routes) {
    const ctx = await browser.newContext({ viewport: { width: 412, height: 823 }, deviceScaleFactor: 1.75, isMobile: true, hasTouch: true, serviceWorkers: 'block' });
    const page = await ctx.newPage();
    await browser.startTracing(page, { categories: ['devtools.timeline', 'disabled-by-default-devtools.timeline', 'v8.execute', 'blink.user_timing'] });
    await page.goto(`http://127.0.0.1:${port}/app/${route}`);
    await page.waitForTimeout(ms);
    const buf = await browser.stopTracing();
    const events = JSON.parse(buf.toString()).traceEvents;
    // the page's renderer main thread: the CrRendererMain thread that parsed our page's HTML
    const names = new Map();
    for (const e of events) if (e.name === 'thread_name') names.set(`${e.pid}:${e.tid}`, e.args.name);
    const ours = events.find((e) => e.name === 'ParseHTML' && String(e.args?.beginData?.url ?? '').includes(`127.0.0.1:${port}`) && names.get(`${e.pid}:${e.tid}`) === 'CrRendererMain');
    if (!ours) throw new Error(`${route}: no trace of the page's main thread`);
    const key = `${ours.pid}:${ours.tid}`;
    const evs = events.filter((e) => `${e.pid}:${e.tid}` === key && e.ph === 'X' && e.dur !== undefined);
    evs.sort((a, b) => a.ts - b.ts || b.dur - a.dur);
    const nav = evs.find((e) => e.name === 'RunTask')?.ts ?? 0;
    const tasks = evs.filter((e) => e.name === 'RunTask' || e.name === 'ThreadControllerImpl::RunTask');
    const long = [];
    for (const t of tasks) {
      if (t.dur / 1000 < min) continue;
      const end = t.ts + t.dur;
      const inside = evs.filter((e) => e !== t && e.ts >= t.ts && e.ts + e.dur <= end);
      const agg = new Map();
      const add = (k, d) => agg.set(k, (agg.get(k) ?? 0) + d);
      for (const e of inside) {
        if (e.name === 'FunctionCall' || e.name === 'EvaluateScript' || e.name === 'v8.callFunction') {
          const d = e.args?.data ?? {};
          const url = String(d.url ?? '').replace(/^.*\/assets\//, '');
          if (e.name !== 'v8.callFunction') add(`js ${d.functionName || '(anon)'} ${url}`, e.dur);
        } else if (['Layout', 'UpdateLayoutTree', 'Paint', 'ParseHTML', 'ParseAuthorStyleSheet', 'MajorGC', 'MinorGC', 'CompositeLayers', 'PrePaint', 'Layerize', 'HitTest', 'FireAnimationFrame', 'TimerFire', 'FireIdleCallback', 'IntersectionObserverController::computeIntersections', 'ResizeObserverController::Notify'].includes(e.name)) {
          add(e.name, e.dur);
        }
      }
      long.push({ start: (t.ts - nav) / 1000, dur: t.dur / 1000, top: [...agg].sort((a, b) => b[1] - a[1]).slice(0, 6) });
    }
    const tbt = long.reduce((s, t) => s + Math.max(0, t.dur * 4 - 50), 0);
    console.log(`\n== ${route}: ${long.length} tasks over ${min} ms; simulated TBT-like (×4, −50) ${tbt.toFixed(0)} ms`);
    for (const t of long) console.log(`${t.start.toFixed(0).padStart(6)} ms  ${t.dur.toFixed(1).padStart(6)} ms  ${t.top.map(([k, d]) => `${k} ${(d / 1000).toFixed(1)}`).join(' | ')}`);
    await ctx.close();
  }
} finally {
  await browser.close();
  server.kill();
}
