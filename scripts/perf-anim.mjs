#!/usr/bin/env node
/**
 * Animation benchmark: plays each scene's animation in the system Chromium at 4× CPU
 * throttling (DevTools Emulation.setCPUThrottlingRate) and records, from a performance trace, the
 * main thread's script time per animation frame (median, p95) and the dropped frames. Writes
 * bench/anim-perf.json and prints a table. A benchmark, not a test: it is not part of `npm test`.
 *
 *   npm run build && node scripts/perf-anim.mjs [--dist dist] [--port 4391] [--seconds 4] [--rate 4] [--routes hemisphere,texture]
 *     [--settle 20] [--frames] [--detail]
 *
 * --frames adds each frame's script time to the results file; --detail prints, for every frame
 * over 8 ms and for the last frame of each recording, its top-level script events (what ran, where,
 * for how long), e.g. to tell a frame's own work from a timer, an idle callback or a worker message.
 *
 * Each route opens paused; once its start-up work is done (1.5 s without a long task, at most
 * `--settle` s) it switches loop on, presses Play, throttles the CPU, waits 1 s, records
 * `--seconds` of trace, and splits the main thread's script
 * events (function calls, timers, animation-frame callbacks, event dispatch, microtasks, parsing,
 * GC is excluded) into frames at each animation-frame callback.
 */
import { spawn } from 'node:child_process';
import { mkdirSync, writeFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { chromium } from 'playwright-core';
import { SCENES } from './catalogue.mjs';
import { CHROMIUM_ARGS, findChromium, NO_CHROMIUM_HELP } from './chromium.mjs';

const args = process.argv.slice(2);
const opt = (name, def) => {
  const i = args.indexOf(name);
  return i < 0 ? def : args[i + 1];
};
const dist = opt('--dist', 'dist');
const port = Number(opt('--port', '4391'));
const seconds = Number(opt('--seconds', '4'));
const rate = Number(opt('--rate', '4'));
const ROUTES = Object.fromEntries(SCENES.map((s) => [s.id, `#${s.path}`]));
const only = opt('--routes', '');
const detail = args.includes('--detail');
const settleMax = Number(opt('--settle', '20'));
const routes = Object.entries(ROUTES).filter(([id]) => !only || only.split(',').includes(id));

const exe = findChromium();
if (!exe) {
  console.error(NO_CHROMIUM_HELP);
  process.exit(1);
}

/** Script-like trace events on the main thread (top-level ones are summed; nested ones are inside them). */
const SCRIPT = new Set([
  'FunctionCall',
  'EvaluateScript',
  'TimerFire',
  'FireAnimationFrame',
  'EventDispatch',
  'RunMicrotasks',
  'v8.compile',
  'FireIdleCallback',
  'XHRReadyStateChange',
  'v8.callFunction',
  'v8.evaluateModule',
]);

function quantile(sorted, q) {
  if (!sorted.length) return NaN;
  const i = Math.min(sorted.length - 1, Math.max(0, Math.ceil(q * sorted.length) - 1));
  return sorted[i];
}

async function readTrace(cdp) {
  const chunks = [];
  const done = new Promise((resolve) => cdp.once('Tracing.tracingComplete', resolve));
  const collect = (e) => chunks.push(...e.value);
  cdp.on('Tracing.dataCollected', collect);
  await cdp.send('Tracing.end');
  await done;
  cdp.off('Tracing.dataCollected', collect);
  return chunks;
}

function analyse(events) {
  // the renderer's main thread: the thread named CrRendererMain with the most script events
  const names = new Map();
  for (const e of events)
    if (e.ph === 'M' && e.name === 'thread_name' && e.args?.name === 'CrRendererMain')
      names.set(`${e.pid}:${e.tid}`, 0);
  for (const e of events) {
    const k = `${e.pid}:${e.tid}`;
    if (names.has(k) && SCRIPT.has(e.name)) names.set(k, names.get(k) + 1);
  }
  const main = [...names.entries()].sort((a, b) => b[1] - a[1])[0]?.[0];
  const ev = events
    .filter((e) => `${e.pid}:${e.tid}` === main && e.ph === 'X' && typeof e.dur === 'number')
    .sort((a, b) => a.ts - b.ts);
  // top-level script intervals (skip those nested inside an earlier one)
  const script = [];
  let end = -Infinity;
  for (const e of ev) {
    if (!SCRIPT.has(e.name)) continue;
    if (e.ts < end) continue;
    script.push(e);
    end = e.ts + e.dur;
  }
  const frames = ev.filter((e) => e.name === 'FireAnimationFrame').map((e) => e.ts);
  const perFrame = [];
  const perFrameCpu = [];
  let j = 0;
  for (let i = 0; i + 1 < frames.length; i++) {
    let sum = 0;
    let cpu = 0;
    while (j < script.length && script[j].ts < frames[i]) j++;
    let k = j;
    while (k < script.length && script[k].ts < frames[i + 1]) {
      cpu += script[k].tdur ?? script[k].dur;
      sum += script[k++].dur;
    }
    perFrame.push(sum / 1000);
    perFrameCpu.push(cpu / 1000);
    if (detail && (sum / 1000 > 8 || i + 2 >= frames.length)) {
      const what = script
        .slice(j, k)
        .filter((e) => e.dur > 1000)
        .map((e) => {
          const d = e.args?.data ?? {};
          const where = d.functionName || d.url?.split('/').pop() || d.type || d.timerId || '';
          return `${e.name}${where ? `(${where}${d.lineNumber ? `:${d.lineNumber}` : ''})` : ''} ${(e.dur / 1000).toFixed(1)}`;
        });
      const all = script
        .slice(j, k)
        .map((e) => `${e.name}@${((e.ts - frames[i]) / 1000).toFixed(1)}+${(e.dur / 1000).toFixed(1)}`);
      console.log(
        `  frame ${i}/${frames.length - 1}: ${(sum / 1000).toFixed(1)} ms: ${what.join(', ')}${i + 2 >= frames.length ? ` | all: ${all.join(' ')}` : ''}`,
      );
    }
  }
  const intervals = [];
  for (let i = 0; i + 1 < frames.length; i++) intervals.push((frames[i + 1] - frames[i]) / 1000);
  const dropped = intervals.reduce((s, dt) => s + Math.max(0, Math.round(dt / (1000 / 60)) - 1), 0);
  const sorted = [...perFrame].sort((a, b) => a - b);
  const sortedCpu = [...perFrameCpu].sort((a, b) => a - b);
  const si = [...intervals].sort((a, b) => a - b);
  return {
    frames: frames.length,
    scriptMsMedian: quantile(sorted, 0.5),
    scriptMsP95: quantile(sorted, 0.95),
    // the main thread's own CPU time in those script events (trace tdur): not inflated when other
    // processes take the machine's cores, and not stretched by the throttling either
    scriptCpuMsMedian: quantile(sortedCpu, 0.5),
    scriptCpuMsP95: quantile(sortedCpu, 0.95),
    frameIntervalMsMedian: quantile(si, 0.5),
    frameIntervalMsP95: quantile(si, 0.95),
    droppedFrames: dropped,
    ...(process.argv.includes('--frames')
      ? {
          perFrameMs: perFrame.map((x) => Math.round(x * 10) / 10),
          perFrameCpuMs: perFrameCpu.map((x) => Math.round(x * 10) / 10),
        }
      : {}),
  };
}

const server = spawn(process.execPath, ['scripts/serve.mjs', dist, String(port)], {
  stdio: ['ignore', 'pipe', 'inherit'],
});
await new Promise((r) => server.stdout.once('data', r));
const browser = await chromium.launch({ executablePath: exe, args: CHROMIUM_ARGS });
const results = [];
try {
  for (const [id, hash] of routes) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`http://127.0.0.1:${port}/app/${hash}`);
    const tl = page.getByTestId('timeline').first();
    try {
      await tl.waitFor({ timeout: 60_000 });
    } catch {
      results.push({ route: id, error: 'no timeline on the page' });
      await context.close();
      continue;
    }
    await tl.scrollIntoViewIfNeeded();
    // The page's own start-up work (lazy chunks, formulas typeset in idle time below the fold)
    // is not the animation's: the page opens paused, unthrottled, and plays only once 1.5 s
    // passed without a long task (or after --settle s; recorded as `settle`).
    const settle = await page.evaluate(
      (maxMs) =>
        new Promise((resolve) => {
          const t0 = performance.now();
          let last = t0;
          let n = 0;
          const po = new PerformanceObserver((list) => {
            for (const e of list.getEntries()) {
              last = Math.max(last, e.startTime + e.duration);
              n++;
            }
          });
          po.observe({ type: 'longtask', buffered: false });
          const check = () => {
            const now = performance.now();
            if (now - last >= 1500 || now - t0 >= maxMs) {
              po.disconnect();
              resolve({ ms: Math.round(now - t0), longTasks: n, quiet: now - last >= 1500 });
            } else setTimeout(check, 250);
          };
          setTimeout(check, 250);
        }),
      settleMax * 1000,
    );
    // loop, so the animation keeps playing for the whole recording
    const loop = tl.getByRole('checkbox', { name: /loop/i });
    if (!(await loop.isChecked())) await loop.check();
    if ((await tl.getAttribute('data-playing')) !== '1')
      await page.getByTestId('timeline-play').first().click();
    const cdp = await context.newCDPSession(page);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate });
    await page.waitForTimeout(1000); // settle at the throttled rate
    await cdp.send('Tracing.start', {
      categories: 'devtools.timeline,v8.execute,disabled-by-default-devtools.timeline',
      transferMode: 'ReportEvents',
    });
    await page.waitForTimeout(seconds * 1000);
    const events = await readTrace(cdp);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: 1 });
    const r = { route: id, settle, ...analyse(events), errors: errors.length ? errors : undefined };
    results.push(r);
    await context.close();
  }
} finally {
  await browser.close();
  server.kill();
}

const out = {
  date: new Date().toISOString(),
  cpuThrottling: rate,
  seconds,
  machine: { cpus: cpus().length, loadavg: loadavg() },
  goal: 'p95 script per frame ≤ 8 ms at 4× throttling',
  results,
};
mkdirSync('bench', { recursive: true });
writeFileSync('bench/anim-perf.json', `${JSON.stringify(out, null, 2)}\n`);
const f = (x) => (typeof x === 'number' && Number.isFinite(x) ? x.toFixed(2) : '—');
console.log(
  `animation at ${rate}× CPU throttling, ${seconds} s each (load ${loadavg()
    .map((x) => x.toFixed(2))
    .join(' ')})`,
);
console.log('route           frames  script/frame median  p95     cpu p95  interval p95  dropped');
for (const r of results) {
  if (r.error) console.log(`${r.route.padEnd(16)}${r.error}`);
  else
    console.log(
      `${r.route.padEnd(16)}${String(r.frames).padStart(6)}  ${f(r.scriptMsMedian).padStart(19)}  ${f(r.scriptMsP95).padStart(6)}  ${f(r.scriptCpuMsP95).padStart(7)}  ${f(r.frameIntervalMsP95).padStart(12)}  ${String(r.droppedFrames).padStart(7)}`,
    );
}
console.log('wrote bench/anim-perf.json');
