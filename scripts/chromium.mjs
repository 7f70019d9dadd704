/** Where the system Chromium is, and the flags this machine needs. Shared by e2e and screenshots. */
import { existsSync } from 'node:fs';
import { execSync } from 'node:child_process';

export const CHROMIUM_ARGS = [
  '--no-sandbox',
  '--disable-gpu',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
];

export function findChromium() {
  const candidates = [
    process.env.CHROMIUM_PATH,
    '/usr/bin/chromium',
    '/usr/bin/chromium-browser',
    '/usr/bin/google-chrome',
  ];
  for (const c of candidates) if (c && existsSync(c)) return c;
  try {
    const p = execSync('command -v chromium || command -v chromium-browser || command -v google-chrome', {
      encoding: 'utf8',
      shell: '/bin/sh',
    }).trim();
    if (p) return p;
  } catch {
    /* none on PATH */
  }
  return null;
}

export const NO_CHROMIUM_HELP = `No Chromium found for the browser tests.
Install one (Debian/Ubuntu):   sudo apt-get update && sudo apt-get install -y chromium
or point CHROMIUM_PATH at an existing Chromium/Chrome binary:   CHROMIUM_PATH=/path/to/chrome npm test
(Playwright's own browser download is not used by this project.)`;
