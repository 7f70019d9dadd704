#!/usr/bin/env node
/** Runs the browser tests (tests/e2e) against the built app in the system Chromium. */
import { existsSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { findChromium, NO_CHROMIUM_HELP } from './chromium.mjs';

const chromium = findChromium();
if (!chromium) {
  console.error(NO_CHROMIUM_HELP);
  process.exit(1);
}
const dist = process.env.E2E_DIST ?? 'dist';
if (!existsSync(`${dist}/index.html`)) {
  console.error(`No build in ${dist}/. Run "npm run build" first (npm test does it for you).`);
  process.exit(1);
}
const r = spawnSync('npx', ['playwright', 'test', ...process.argv.slice(2)], {
  stdio: 'inherit',
  env: { ...process.env, CHROMIUM_PATH: chromium, E2E_DIST: dist },
});
process.exit(r.status ?? 1);
