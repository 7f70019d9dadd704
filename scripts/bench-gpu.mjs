#!/usr/bin/env node
/**
 * GPU benchmark (not a test): the frame time of the hemisphere scene's vertex-shader pass, which
 * makes and draws 10⁶ directions (src/scenes/hemisphere/view/gpu/warpShader.ts), in headless Chromium
 * against the built app. The page's own "Time 20 frames" button times each frame as draw +
 * a one-pixel read back (which waits for the GPU), median of 20; this script presses it `--runs`
 * times for each form and records the medians, the renderer and the first pass's times.
 *
 *   npx vite build && node scripts/bench-gpu.mjs [--runs 3] [--port 4462] [--dist dist] [--gpu]
 *
 * By default Chromium runs with the repository's flags (--disable-gpu): WebGL2 is then
 * SwiftShader, a CPU implementation, so the number measures the CPU, not a GPU. `--gpu` drops
 * --disable-gpu and adds --ignore-gpu-blocklist (plus any `--chrome-flag=…`), for a machine with
 * a real GPU and drivers. Writes bench/gpu.json.
 */
import { spawn } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, findChromium, NO_CHROMIUM_HELP } from './chromium.mjs';

const argv = process.argv.slice(2);
const opt = (name, def) => {
  const i = argv.indexOf(name);
  return i < 0 ? def : argv[i + 1];
};
const runs = Number(opt('--runs', '3'));
const port = Number(opt('--port', '4462'));
const dist = opt('--dist', 'dist');
const gpu = argv.includes('--gpu');
const extra = argv.filter((a) => a.startsWith('--chrome-flag=')).map((a) => a.slice('--chrome-flag='.length));

const exe = findChromium();
if (!exe) {
  console.error(NO_CHROMIUM_HELP);
  process.exit(1);
}
const args = gpu
  ? [...CHROMIUM_ARGS.filter((a) => a !== '--disable-gpu'), '--ignore-gpu-blocklist', ...extra]
  : [...CHROMIUM_ARGS, ...extra];

const server = spawn('node', ['scripts/serve.mjs', dist, String(port)], { stdio: 'ignore' });
const browser = await chromium.launch({ executablePath: exe, args });
const out = {
  generatedAt: new Date().toISOString(),
  what: 'hemisphere GPU warp pass: 10⁶ directions made and drawn by a vertex shader, ms per frame (draw + 1-pixel read back), median of 20 frames per run',
  chromiumArgs: args,
  machine: { cpu: cpus()[0]?.model ?? 'unknown', cpus: cpus().length, loadAverageAtStart: loadavg() },
  renderer: null,
  forms: {},
  firstPass: {},
};
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 } });
  for (let i = 0; i < 50; i++) {
    try {
      await page.goto(`http://127.0.0.1:${port}/app/#/hemisphere?seed=7`);
      break;
    } catch {
      await new Promise((r) => setTimeout(r, 200));
    }
  }
  await page.waitForSelector('main#main');
  const details = page.getByTestId('gpu-warp-details');
  await details.waitFor({ timeout: 60_000 });
  await details.scrollIntoViewIfNeeded();
  await details.locator('summary').click();
  await page.getByTestId('gpu-warp-panel').waitFor({ timeout: 60_000 });
  if (await page.getByTestId('gpu-warp-unavailable').count()) {
    throw new Error(`no WebGL2: ${await page.getByTestId('gpu-warp-unavailable').innerText()}`);
  }
  const value = (id) => page.getByTestId(id).first().getAttribute('data-value');
  for (const form of [1, 0]) {
    await page.getByTestId(`gpu-warp-form-${form}`).check();
    await page.waitForFunction(
      () =>
        /yes|no/.test(
          document.querySelector('[data-testid="gpu-chi2-pass"]')?.getAttribute('data-value') ?? '',
        ),
      null,
      { timeout: 120_000 },
    );
    out.renderer = await page.getByTestId('gpu-warp-renderer').innerText();
    out.firstPass[form === 1 ? 'stable' : 'textbook'] = await page.getByTestId('gpu-warp-times').innerText();
    const medians = [];
    for (let r = 0; r < runs; r++) {
      const before = await value('gpu-warp-frame-ms');
      await page.getByTestId('gpu-warp-time').click();
      await page.waitForFunction(
        (b) => {
          const v = document.querySelector('[data-testid="gpu-warp-frame-ms"]')?.getAttribute('data-value');
          return v && v !== 'none' && v !== b;
        },
        r === 0 ? 'none' : before,
        { timeout: 120_000 },
      );
      medians.push(Number(await value('gpu-warp-frame-ms')));
    }
    out.forms[form === 1 ? 'stable' : 'textbook'] = {
      msPerFrameMedians: medians,
      msPerFrame: [...medians].sort((a, b) => a - b)[medians.length >> 1],
      chi2p: Number(await value('gpu-chi2-p')),
    };
  }
  out.machine.loadAverageAtEnd = loadavg();
  writeFileSync('bench/gpu.json', `${JSON.stringify(out, null, 2)}\n`);
  console.log(`renderer: ${out.renderer}`);
  for (const [k, v] of Object.entries(out.forms))
    console.log(
      `${k}: ${v.msPerFrame.toFixed(1)} ms per 10⁶-direction frame (runs: ${v.msPerFrameMedians.map((x) => x.toFixed(1)).join(', ')}), χ² p = ${v.chi2p}`,
    );
  if (!gpu)
    console.log('(SwiftShader: a CPU implementation of WebGL2; run with --gpu on a machine with a GPU)');
} finally {
  await browser.close();
  server.kill();
}
