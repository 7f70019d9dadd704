#!/usr/bin/env node
/**
 * GPU benchmark (not a test): the frame time of the hemisphere scene's vertex-shader pass, which
 * makes and draws 10⁶ directions (src/scenes/hemisphere/view/gpu/warpShader.ts), and the render
 * lab's GPU renderer in samples per second (src/scenes/render/gpu/), in headless Chromium against
 * the built app. The page's own "Time 20 frames" button times each frame as draw +
 * a one-pixel read back (which waits for the GPU), median of 20; this script presses it `--runs`
 * times for each form and records the medians, the renderer and the first pass's times. The render lab renders a 256 × 256 image of the exam
 * scene (mis-power, 1 bounce) and of the white furnace (mis-power, 3 bounces) to `--render-spp`
 * samples per pixel (default 32; 256 with --gpu) and records the page's own `samples-per-second`
 * readout: pixels × samples per pixel per second of the run, one sample per pixel per displayed
 * frame (so on a fast GPU the display's frame rate caps it).
 *
 *   npx vite build && node scripts/bench-gpu.mjs [--runs 3] [--port 4462] [--dist dist] [--gpu] [--render-spp 32]
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
const renderSpp = Number(opt('--render-spp', gpu ? '256' : '32'));
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
  // the render lab's GPU renderer: samples per second at 256², as the page reports them
  out.renderLab = {
    what: `render lab GPU renderer (WebGL2 fragment shader, float32): 256 × 256 pixels × ${renderSpp} samples per pixel, the page's samples-per-second readout (one sample per pixel per frame)`,
    runs: {},
  };
  for (const [name, query] of [
    ['exam, mis-power, 1 bounce', 'scene=exam&strategy=mis-power&bounces=1'],
    ['furnace, mis-power, 3 bounces', 'scene=furnace&strategy=mis-power&bounces=3'],
  ]) {
    await page.goto(`http://127.0.0.1:${port}/app/#/render?res=256&spp=${renderSpp}&${query}`);
    await page.waitForSelector('main#main');
    await page.evaluate(() => window.scrollTo(0, 0));
    await page.waitForFunction(
      () => /^Done/.test(document.querySelector('[data-testid="render-status"]')?.textContent ?? ''),
      null,
      { timeout: 600_000 },
    );
    const renderer = await value('renderer');
    if (renderer !== 'gpu')
      throw new Error(
        `the render lab drew with ${renderer}: ${await page.getByTestId('render-gpu-unavailable').innerText()}`,
      );
    out.renderLab.runs[name] = {
      samplesPerSecond: Number(await value('samples-per-second')),
      rendererNote: await page
        .getByTestId('renderer')
        .locator('xpath=..')
        .locator('.readout-note')
        .innerText(),
    };
  }
  out.machine.loadAverageAtEnd = loadavg();
  writeFileSync('bench/gpu.json', `${JSON.stringify(out, null, 2)}\n`);
  console.log(`renderer: ${out.renderer}`);
  for (const [k, v] of Object.entries(out.forms))
    console.log(
      `${k}: ${v.msPerFrame.toFixed(1)} ms per 10⁶-direction frame (runs: ${v.msPerFrameMedians.map((x) => x.toFixed(1)).join(', ')}), χ² p = ${v.chi2p}`,
    );
  for (const [k, v] of Object.entries(out.renderLab.runs))
    console.log(
      `render lab, ${k}: ${(v.samplesPerSecond / 1e6).toFixed(3)} M samples per second at 256² (${v.rendererNote})`,
    );
  if (!gpu)
    console.log('(SwiftShader: a CPU implementation of WebGL2; run with --gpu on a machine with a GPU)');
} finally {
  await browser.close();
  server.kill();
}
