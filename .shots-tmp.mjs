import { spawn } from 'node:child_process';
import { chromium } from 'playwright-core';
const server = spawn(process.execPath, ['scripts/serve.mjs', 'dist', '4323'], { stdio: ['ignore', 'pipe', 'inherit'] });
await new Promise((r) => server.stdout.once('data', r));
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox', '--disable-gpu'] });
const shots = JSON.parse(process.argv[2]);
try {
  for (const s of shots) {
    const page = await browser.newPage({ viewport: { width: s.w, height: 900 } });
    const errs = [];
    page.on('console', (m) => m.type() === 'error' && errs.push(m.text()));
    await page.goto(`http://127.0.0.1:4323/app/${s.hash}`);
    await page.waitForTimeout(1200);
    for (const [name, text] of s.fill ?? []) await page.getByTestId(`answer-${name}`).fill(text);
    if (s.check) { await page.getByRole('button', { name: 'Check', exact: true }).click(); await page.waitForTimeout(1500); }
    await page.screenshot({ path: s.out, fullPage: true });
    console.log('wrote', s.out, errs.join(' | '));
    await page.close();
  }
} finally { await browser.close(); server.kill(); }
