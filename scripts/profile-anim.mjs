#!/usr/bin/env node
/**
 * Where a playing animation spends its main-thread time: a CPU profile (CDP Profiler, 4× CPU
 * throttling) of a route of the built app while its shared timeline plays, aggregated by function
 * (self time) and by inclusive time within the app's scripts. A diagnostic for issue 12's
 * frame-time goal (see scripts/perf-anim.mjs for the benchmark), not a test. For readable names,
 * build without minifying: `npx vite build --outDir dist-prof --minify false`.
 *
 *   node scripts/profile-anim.mjs [--dist dist-prof] [--port 4432] [--ms 4000] [--top 30] '#/texture?play=1' …
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
const dist = opt('--dist', 'dist-prof');
const port = Number(opt('--port', '4432'));
const ms = Number(opt('--ms', '4000'));
const top = Number(opt('--top', '30'));
const routes = args.length ? args : ['#/texture?play=1'];

const server = spawn(process.execPath, ['scripts/serve.mjs', dist, String(port)], { stdio: ['ignore', 'pipe', 'inherit'] });
await new Promise((r) => server.stdout.once('data', r));
const browser = await chromium.launch({ executablePath: findChromium(), args: CHROMIUM_ARGS });
try {
  for (const route of routes) {
    const ctx = await browser.newContext({ viewport: { width: 1280, height: 900 } });
    const page = await ctx.newPage();
    await page.goto(`http://127.0.0.1:${port}/app/${route}`);
    const tl = page.getByTestId('timeline').first();
    await tl.waitFor({ timeout: 60_000 });
    await tl.scrollIntoViewIfNeeded();
    const loop = tl.getByRole('checkbox', { name: /loop/i });
    if (!(await loop.isChecked())) await loop.check();
    if ((await tl.getAttribute('data-playing')) !== '1') await page.getByTestId('timeline-play').first().click();
    const cdp = await ctx.newCDPSession(page);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: 4 });
    await page.waitForTimeout(1000);
    await cdp.send('Profiler.enable');
    await cdp.send('Profiler.setSamplingInterval', { interval: 100 });
    await cdp.send('Profiler.start');
    await page.waitForTimeout(ms);
    const { profile } = await cdp.send('Profiler.stop');
    const frames = await page.evaluate(() => document.querySelector('[data-testid=timeline]')?.getAttribute('data-t'));
    const nodes = new Map(profile.nodes.map((n) => [n.id, n]));
    const parent = new Map();
    for (const n of profile.nodes) for (const c of n.children ?? []) parent.set(c, n.id);
    const byFn = new Map();
    const incl = new Map();
    const byUrl = new Map();
    let total = 0;
    for (let i = 0; i < profile.samples.length; i++) {
      const id = profile.samples[i];
      const t = (profile.timeDeltas[i + 1] ?? 0) / 1000;
      const cf = nodes.get(id).callFrame;
      if (cf.functionName === '(idle)' || cf.functionName === '(program)') continue;
      total += t;
      const url = cf.url.replace(/^.*\/assets\//, '');
      const k = `${cf.functionName || '(anon)'}  ${url}:${cf.lineNumber + 1}`;
      byFn.set(k, (byFn.get(k) ?? 0) + t);
      byUrl.set(url || cf.functionName, (byUrl.get(url || cf.functionName) ?? 0) + t);
      const seen = new Set();
      for (let x = id; x !== undefined; x = parent.get(x)) {
        const c = nodes.get(x).callFrame;
        if (!c.url.includes('/assets/')) continue;
        const kk = `${c.functionName || '(anon)'}  ${c.url.replace(/^.*\/assets\//, '')}:${c.lineNumber + 1}`;
        if (seen.has(kk)) continue;
        seen.add(kk);
        incl.set(kk, (incl.get(kk) ?? 0) + t);
      }
    }
    console.log(`\n== ${route}: busy ${total.toFixed(0)} ms of ${ms} ms (t now ${frames})`);
    console.log('-- by script');
    for (const [k, v] of [...byUrl].sort((a, b) => b[1] - a[1]).slice(0, 10)) console.log(`${v.toFixed(0).padStart(7)} ms  ${k}`);
    console.log('-- by function (self)');
    for (const [k, v] of [...byFn].sort((a, b) => b[1] - a[1]).slice(0, top)) console.log(`${v.toFixed(0).padStart(7)} ms  ${k}`);
    console.log('-- inclusive (app scripts)');
    for (const [k, v] of [...incl].sort((a, b) => b[1] - a[1]).slice(0, top)) console.log(`${v.toFixed(0).padStart(7)} ms  ${k}`);
    await ctx.close();
  }
} finally {
  await browser.close();
  server.kill();
}
