#!/usr/bin/env node
/**
 * Runs npm scripts side by side and reports each one's output whole, in the order given, once all
 * have finished; exits non-zero if any failed. `npm test` runs its static checks this way (the
 * type check, ESLint and Prettier are each single-threaded, so together they use both cores of a
 * small machine instead of one after another), and likewise the two builds.
 *
 *   node scripts/parallel.mjs typecheck lint:eslint lint:prettier
 */
import { spawn } from 'node:child_process';

const names = process.argv.slice(2);
if (names.length === 0) {
  console.error('usage: node scripts/parallel.mjs SCRIPT [SCRIPT …]   (npm scripts of package.json)');
  process.exit(2);
}

/** One npm script run to its end: its exit code and everything it printed, interleaved as printed. */
function run(name) {
  return new Promise((resolve) => {
    const child = spawn('npm', ['run', '--silent', name], { stdio: ['ignore', 'pipe', 'pipe'] });
    const out = [];
    child.stdout.on('data', (d) => out.push(d));
    child.stderr.on('data', (d) => out.push(d));
    child.on('error', (e) => resolve({ name, code: 1, text: String(e) }));
    child.on('close', (code) => resolve({ name, code: code ?? 1, text: Buffer.concat(out).toString() }));
  });
}

const started = Date.now();
const results = await Promise.all(names.map(run));
let failed = 0;
for (const r of results) {
  console.log(`\n> ${r.name}: ${r.code === 0 ? 'passed' : `FAILED (exit ${r.code})`}`);
  if (r.text.trim()) console.log(r.text.trimEnd());
  if (r.code !== 0) failed++;
}
console.log(
  `\n${names.join(', ')}: ${results.length - failed} passed, ${failed} failed (${((Date.now() - started) / 1000).toFixed(0)} s)`,
);
process.exit(failed ? 1 : 0);
