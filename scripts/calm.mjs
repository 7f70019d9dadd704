#!/usr/bin/env node
/**
 * How calm each page is: tab stops in the first screen and on the page as it opens (folded parts
 * closed), and its height in screens, at 1280×800 and 375×812, for every route of the catalogue
 * (or the routes given). Needs a build (`npm run build`).
 *   node scripts/calm.mjs [--port 4391] ['#/hemisphere' ...]
 */
import { spawn } from 'node:child_process';
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, findChromium, NO_CHROMIUM_HELP } from './chromium.mjs';
import { loadTs } from './loadTs.mjs';

const args = process.argv.slice(2);
const pi = args.indexOf('--port');
const port = pi >= 0 ? Number(args.splice(pi, 2)[1]) : 4391;
const verbose = args.includes('-v') ? (args.splice(args.indexOf('-v'), 1), true) : false;
const { countTabStops } = await loadTs('tests/e2e/calmCount.ts');
const { SCENES } = await loadTs('src/kit/catalogue.ts');
const routes = args.length ? args : SCENES.map((s) => `#${s.path}`);

const exe = findChromium();
if (!exe) {
  console.error(NO_CHROMIUM_HELP);
  process.exit(1);
}
const server = spawn(process.execPath, ['scripts/serve.mjs', 'dist', String(port)], {
  stdio: ['ignore', 'pipe', 'inherit'],
});
await new Promise((r) => server.stdout.once('data', r));
const browser = await chromium.launch({ executablePath: exe, args: CHROMIUM_ARGS });
try {
  console.log('route'.padEnd(28), 'size       first  page  screens');
  for (const route of routes) {
    for (const [w, h] of [
      [1280, 800],
      [375, 812],
    ]) {
      const page = await browser.newPage({ viewport: { width: w, height: h } });
      await page.goto(`http://127.0.0.1:${port}/app/${route}`);
      await page.waitForSelector('main#main', { timeout: 60_000 });
      await page.waitForFunction(() => !document.querySelector('main .loading'), null, { timeout: 60_000 });
      // every lazily mounted section of the page as it opens (folded parts stay closed)
      await page.evaluate(() => window.dispatchEvent(new Event('beforeprint')));
      await page.evaluate(() => window.dispatchEvent(new Event('afterprint')));
      await page.waitForFunction(() => !document.querySelector('[data-deferred="pending"]'), null, {
        timeout: 60_000,
      });
      // lazy views (the 3D view's buttons) and statistics arrive after the sections mount
      await page.waitForLoadState('networkidle');
      await page.waitForFunction(() => !document.querySelector('.math-pending'), null, { timeout: 60_000 });
      const c = await page.evaluate(countTabStops);
      console.log(
        route.padEnd(28),
        `${w}×${h}`.padEnd(10),
        String(c.firstScreen).padStart(5),
        String(c.page).padStart(5),
        String(c.screens).padStart(8),
      );
      if (verbose) console.log('   first screen:', c.first.join(' | '));
      await page.close();
    }
  }
} finally {
  await browser.close();
  server.kill();
}
