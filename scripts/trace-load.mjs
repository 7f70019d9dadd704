#!/usr/bin/env node
/**
 * The long main-thread tasks of a route's load, as Lighthouse sees them: a Chromium trace without
 * CPU throttling (Lighthouse's simulator multiplies each task by 4, so a task over 12.5 ms here is
 * a "long task" there), each task listed with what ran inside it (script by function, style,
 * layout, paint, HTML parsing). A diagnostic for load performance, not a test.
 *
 * Durations are (unless --wall) the main thread's CPU time (the trace's thread duration), not wall time, so that
 * a machine busy with other work still shows what the page itself costs; on a quiet machine the
 * two agree (Lighthouse uses wall time).
 *
 * TRACE_SAVE=file.json keeps the last route's raw trace (for a closer look at its events).
 *
 *   node scripts/trace-load.mjs [--dist dist] [--port 4338] [--ms 8000] [--min 12.5] [--js] [--wall] [--threads] '#/texture' …
 */
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, findChromium } from './chromium.mjs';
import { serveDist, takeOpt, PHONE_CONTEXT, traceProfileSamples } from './cpuprofile.mjs';

function takeFlag(list, name) {
  const i = list.indexOf(name);
  if (i < 0) return false;
  list.splice(i, 1);
  return true;
}

const args = process.argv.slice(2);
const opt = (n, d) => takeOpt(args, n, d);
const dist = opt('--dist', 'dist');
const port = Number(opt('--port', '4338'));
const ms = Number(opt('--ms', '8000'));
const min = Number(opt('--min', '12.5'));
// --js: also sample the JavaScript stacks and list, per long task, the functions that took its time
const withJs = takeFlag(args, '--js');
// --wall: wall time instead of CPU time (what Lighthouse measures: it includes the main thread's
// waits, e.g. on a software WebGL frame read back from the GPU process; only meaningful when quiet)
const useWall = takeFlag(args, '--wall');
// --threads: also the busy CPU time of every thread of the browser (what competes for the cores)
const withThreads = takeFlag(args, '--threads');
const routes = args.length ? args : ['#/hemisphere'];

const server = await serveDist(dist, port);
const browser = await chromium.launch({ executablePath: findChromium(), args: CHROMIUM_ARGS });
try {
  for (const route of routes) {
    const ctx = await browser.newContext(PHONE_CONTEXT);
    const page = await ctx.newPage();
    await browser.startTracing(page, {
      categories: [
        'devtools.timeline',
        'disabled-by-default-devtools.timeline',
        'v8.execute',
        'blink.user_timing',
        ...(withJs ? ['disabled-by-default-v8.cpu_profiler'] : []),
        ...(withThreads ? ['toplevel'] : []),
      ],
    });
    await page.goto(`http://127.0.0.1:${port}/app/${route}`);
    await page.waitForTimeout(ms);
    const buf = await browser.stopTracing();
    const events = JSON.parse(buf.toString()).traceEvents;
    if (process.env.TRACE_SAVE) (await import('node:fs')).writeFileSync(process.env.TRACE_SAVE, buf);
    // the page's renderer main thread: the CrRendererMain thread that parsed our page's HTML
    const names = new Map();
    for (const e of events) if (e.name === 'thread_name') names.set(`${e.pid}:${e.tid}`, e.args.name);
    const ours = events.find(
      (e) =>
        e.name === 'ParseHTML' &&
        String(e.args?.beginData?.url ?? '').includes(`127.0.0.1:${port}`) &&
        names.get(`${e.pid}:${e.tid}`) === 'CrRendererMain',
    );
    if (!ours) throw new Error(`${route}: no trace of the page's main thread`);
    const key = `${ours.pid}:${ours.tid}`;
    const evs = events
      .filter((e) => `${e.pid}:${e.tid}` === key && e.ph === 'X' && e.dur !== undefined)
      .map((e) => ({ ...e, wall: e.dur, dur: useWall ? e.dur : (e.tdur ?? e.dur) }));
    // JS samples of our thread (ProfileChunk events), as [time µs, node id], with the node tree
    const { nodes, samples } = withJs ? traceProfileSamples(events, key) : { nodes: new Map(), samples: [] };
    const frameName = (n) =>
      `${n.callFrame.functionName || '(anon)'} ${String(n.callFrame.url).replace(/^.*\/assets\//, '')}`;
    evs.sort((a, b) => a.ts - b.ts || b.dur - a.dur);
    const nav = evs.find((e) => e.name === 'RunTask')?.ts ?? 0;
    // top-level tasks only (with --threads the 'toplevel' category nests one task event in another)
    let until = -Infinity;
    const tasks = evs.filter((e) => {
      if (e.name !== 'RunTask' && e.name !== 'ThreadControllerImpl::RunTask') return false;
      if (e.ts < until) return false;
      until = e.ts + e.wall;
      return true;
    });
    const long = [];
    for (const t of tasks) {
      if (t.dur / 1000 < min) continue;
      const end = t.ts + t.wall;
      const inside = evs.filter((e) => e !== t && e.ts >= t.ts && e.ts + e.wall <= end);
      const agg = new Map();
      const add = (k, d) => agg.set(k, (agg.get(k) ?? 0) + d);
      for (const e of inside) {
        if (e.name === 'FunctionCall' || e.name === 'EvaluateScript' || e.name === 'v8.callFunction') {
          const d = e.args?.data ?? {};
          const url = String(d.url ?? '').replace(/^.*\/assets\//, '');
          if (e.name !== 'v8.callFunction') add(`js ${d.functionName || '(anon)'} ${url}`, e.dur);
        } else if (
          e.args?.data?.stackTrace === undefined &&
          !/^(ThreadControllerImpl|RunTask|ScheduledAction|v8\.|V8\.)/.test(e.name)
        ) {
          // direct children of the task only for the rest (nested ones are inside those)
          if (
            !inside.some(
              (o) =>
                o !== e &&
                o.name !== 'FunctionCall' &&
                o.ts <= e.ts &&
                o.ts + o.wall >= e.ts + e.wall &&
                o.wall > e.wall,
            )
          )
            add(e.name, e.dur);
        }
      }
      let js = '';
      if (withJs) {
        // inclusive time per function of the app's own chunks (not React, not the browser)
        const inc = new Map();
        let n = 0;
        for (const [time, id] of samples) {
          if (time < t.ts || time > end) continue;
          n++;
          const seen = new Set();
          for (let node = nodes.get(id); node; node = nodes.get(node.parent)) {
            const url = String(node.callFrame.url);
            if (!/\/assets\//.test(url) || /\/assets\/(index|jsx-runtime|vendor-)/.test(url)) continue;
            const k = frameName(node);
            if (seen.has(k)) continue;
            seen.add(k);
            inc.set(k, (inc.get(k) ?? 0) + 1);
          }
        }
        // and React's own phases (render, commit, effects) by inclusive share
        const phases = new Map();
        for (const [time, id] of samples) {
          if (time < t.ts || time > end) continue;
          const seen = new Set();
          for (let node = nodes.get(id); node; node = nodes.get(node.parent)) {
            const fn = node.callFrame.functionName;
            if (
              !/^(renderRootSync|renderRootConcurrent|commitRoot|flushPassiveEffects|commitLayoutEffects|flushLayoutEffects|commitMutationEffects|flushMutationEffects|recursivelyTraversePassiveMountEffects)$/.test(
                fn,
              ) ||
              seen.has(fn)
            )
              continue;
            seen.add(fn);
            phases.set(fn, (phases.get(fn) ?? 0) + 1);
          }
        }
        const pct = (list) =>
          [...list]
            .sort((a, b) => b[1] - a[1])
            .slice(0, 6)
            .map(([k, c]) => `${k} ${Math.round((100 * c) / n)}%`)
            .join(' | ');
        // and the functions with the most self time, any script (the shell lives in the entry chunk)
        const self = new Map();
        for (const [time, id] of samples) {
          if (time < t.ts || time > end) continue;
          const node = nodes.get(id);
          if (!node || /^\((idle|program|garbage collector|root)\)$/.test(node.callFrame.functionName))
            continue;
          const k = frameName(node);
          self.set(k, (self.get(k) ?? 0) + 1);
        }
        if (n)
          js = `\n${' '.repeat(26)}app code: ${pct(inc)}\n${' '.repeat(26)}React: ${pct(phases)}\n${' '.repeat(26)}self: ${pct(self)}`;
      }
      long.push({
        start: (t.ts - nav) / 1000,
        dur: t.dur / 1000,
        top: [...agg].sort((a, b) => b[1] - a[1]).slice(0, 6),
        js,
      });
    }
    if (withThreads) {
      // every thread's busy CPU time in the first --ms: what competes with the main thread for the
      // machine's cores (workers, the GPU process's rasterizer, the compositor…)
      const busy = new Map();
      for (const e of events) {
        if (
          e.ph !== 'X' ||
          (e.name !== 'RunTask' &&
            e.name !== 'ThreadControllerImpl::RunTask' &&
            e.name !== 'ThreadPool_RunTask')
        )
          continue;
        const k = `${e.pid}:${e.tid}`;
        busy.set(k, (busy.get(k) ?? 0) + (e.tdur ?? e.dur) / 1000);
      }
      const rows = [...busy].sort((a, b) => b[1] - a[1]).slice(0, 12);
      console.log(`\n${route}: CPU per thread (ms), the page's main thread is ${key}`);
      for (const [k, v] of rows) console.log(`  ${v.toFixed(0).padStart(6)}  ${names.get(k) ?? '?'} (${k})`);
    }
    const tbt = long.reduce((s, t) => s + Math.max(0, t.dur * 4 - 50), 0);
    console.log(
      `\n== ${route}: ${long.length} tasks over ${min} ms of main-thread CPU; simulated TBT-like (×4, −50) ${tbt.toFixed(0)} ms`,
    );
    for (const t of long)
      console.log(
        `${t.start.toFixed(0).padStart(6)} ms  ${t.dur.toFixed(1).padStart(6)} ms  ${t.top.map(([k, d]) => `${k} ${(d / 1000).toFixed(1)}`).join(' | ')}${t.js}`,
      );
    await ctx.close();
  }
} finally {
  await browser.close();
  server.kill();
}
