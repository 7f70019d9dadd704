#!/usr/bin/env node
/**
 * Where a playing animation spends its main-thread time: a CPU profile (CDP Profiler, 4× CPU
 * throttling) of a route of the built app while its shared timeline plays, aggregated by function
 * (self time) and by inclusive time within the app's scripts. A diagnostic for the animation
 * frame-time goal (see scripts/perf-anim.mjs for the benchmark), not a test. For readable names,
 * build without minifying: `npx vite build --outDir dist-prof --minify false`.
 *
 *   node scripts/profile-anim.mjs [--dist dist-prof] [--port 4432] [--ms 4000] [--top 30] '#/texture?play=1' …
 */
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, findChromium } from './chromium.mjs';
import { serveDist, summarize, takeOpt } from './cpuprofile.mjs';

const args = process.argv.slice(2);
const opt = (n, d) => takeOpt(args, n, d);
const dist = opt('--dist', 'dist-prof');
const port = Number(opt('--port', '4432'));
const ms = Number(opt('--ms', '4000'));
const top = Number(opt('--top', '30'));
const routes = args.length ? args : ['#/texture?play=1'];

const server = await serveDist(dist, port);
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
    if ((await tl.getAttribute('data-playing')) !== '1')
      await page.getByTestId('timeline-play').first().click();
    const cdp = await ctx.newCDPSession(page);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: 4 });
    await page.waitForTimeout(1000);
    await cdp.send('Profiler.enable');
    await cdp.send('Profiler.setSamplingInterval', { interval: 100 });
    await cdp.send('Profiler.start');
    await page.waitForTimeout(ms);
    const { profile } = await cdp.send('Profiler.stop');
    const frames = await page.evaluate(() =>
      document.querySelector('[data-testid=timeline]')?.getAttribute('data-t'),
    );
    const sum = summarize(profile, { top, withInclusive: true });
    console.log(`\n== ${route}: busy ${sum.total.toFixed(0)} ms of ${ms} ms (t now ${frames})`);
    sum.print();
    await ctx.close();
  }
} finally {
  await browser.close();
  server.kill();
}
