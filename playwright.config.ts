import { defineConfig } from '@playwright/test';
// @ts-expect-error plain ESM helper without types
import { CHROMIUM_ARGS, findChromium } from './scripts/chromium.mjs';

const port = Number(process.env.E2E_PORT ?? 4317);
const dist = process.env.E2E_DIST ?? 'dist';

export default defineConfig({
  testDir: 'tests/e2e',
  testMatch: /.*\.spec\.ts$/,
  fullyParallel: true,
  workers: process.env.E2E_WORKERS ? Number(process.env.E2E_WORKERS) : 2,
  // No retries: a test that fails only sometimes is a bug in the test (waiting for a time instead of
  // a state) or in the app, and is fixed rather than retried.
  retries: 0,
  timeout: 60_000,
  expect: { timeout: 15_000 },
  reporter: process.env.CI ? [['list']] : [['list']],
  use: {
    baseURL: `http://127.0.0.1:${port}/app/`,
    browserName: 'chromium',
    launchOptions: { executablePath: (findChromium() as string | null) ?? undefined, args: CHROMIUM_ARGS },
    viewport: { width: 1280, height: 900 },
    permissions: ['clipboard-read', 'clipboard-write'],
    // The service worker precaches the whole build in the background; only the offline tests
    // (tests/e2e/offline.spec.ts) need it, so the others do not pay for it.
    serviceWorkers: 'block',
    // A worker's tests share one browser context, reset by Playwright between tests (pages back to
    // about:blank; storage, routes, init scripts, viewport and media as configured): a fresh
    // context and its renderer cost about a CPU-second each, some 15 % of the suite. A test whose
    // options differ beyond viewport and media (offline.spec's service workers, a touch screen)
    // gets a fresh one; tests/e2e/fixtures.ts puts the offline switch back.
    reuseContext: true,
  },
  webServer: {
    command: `node scripts/serve.mjs ${dist} ${port}`,
    url: `http://127.0.0.1:${port}/app/`,
    reuseExistingServer: false,
    timeout: 20_000,
    stdout: 'ignore',
  },
});
