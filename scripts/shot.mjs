#!/usr/bin/env node
/**
 * Screenshot a route of the built app in the system Chromium.
 *   node scripts/shot.mjs [--dist dist] [--port 4390] [--wait ms] [--full] '#/texture?u=0.4' out.png [width=1280] [height=900]
 */
import { spawn } from 'node:child_process';
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, findChromium, NO_CHROMIUM_HELP } from './chromium.mjs';

const args = process.argv.slice(2);
const opt = (name, def) => {
  const i = args.indexOf(name);
  if (i < 0) return def;
  const v = args[i + 1];
  args.splice(i, 2);
  return v;
};
const flag = (name) => {
  const i = args.indexOf(name);
  if (i < 0) return false;
  args.splice(i, 1);
  return true;
};
const dist = opt('--dist', 'dist');
const port = Number(opt('--port', '4390'));
const wait = Number(opt('--wait', '1500'));
const full = flag('--full');
const [hash = '#/', out = '/tmp/shot.png', width = '1280', height = '900'] = args;

const exe = findChromium();
if (!exe) {
  console.error(NO_CHROMIUM_HELP);
  process.exit(1);
}
const server = spawn(process.execPath, ['scripts/serve.mjs', dist, String(port)], {
  stdio: ['ignore', 'pipe', 'inherit'],
});
await new Promise((r) => server.stdout.once('data', r));
const browser = await chromium.launch({ executablePath: exe, args: CHROMIUM_ARGS });
try {
  const page = await browser.newPage({ viewport: { width: Number(width), height: Number(height) } });
  const errors = [];
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(`http://127.0.0.1:${port}/app/${hash}`);
  await page.waitForTimeout(wait);
  await page.screenshot({ path: out, fullPage: full });
  console.log(`wrote ${out}${errors.length ? `\nconsole errors:\n  ${errors.join('\n  ')}` : ''}`);
} finally {
  await browser.close();
  server.kill();
}
