#!/usr/bin/env node
/**
 * Writes dist-lms/: SCORM 1.2, SCORM 2004 and cmi5 packages of the practice questions (the
 * single-file build as launch page) and the question banks (Moodle XML, QTI 2.1).
 *
 *   npm run build:lms                          all six questions, 5 variants each, seed 1
 *   npm run build:lms -- --questions 1,3,5 --variants 10 --seed 7 --mastery 0.8
 *   node scripts/build-lms.mjs --app dist      the static build's files as the launch page instead
 *
 * The generators are the app's own TypeScript modules, loaded through Vite's SSR loader.
 */
import { mkdirSync, readFileSync, readdirSync, statSync, writeFileSync, existsSync } from 'node:fs';
import { join, relative } from 'node:path';
import { createServer } from 'vite';
import katex from 'katex';

function arg(name, fallback) {
  const i = process.argv.indexOf(`--${name}`);
  return i >= 0 && i + 1 < process.argv.length ? process.argv[i + 1] : fallback;
}
function fail(msg) {
  console.error(`build:lms: ${msg}`);
  process.exit(1);
}

const appDir = arg('app', 'dist-single');
const out = arg('out', 'dist-lms');
const variants = Number(arg('variants', '5'));
const seed = Number(arg('seed', '1'));
const mastery = Number(arg('mastery', '0.8'));
if (!Number.isInteger(variants) || variants < 1 || variants > 200)
  fail('--variants must be a whole number from 1 to 200');
if (!Number.isInteger(seed) || seed < 0 || seed > 0xffffffff)
  fail(`--seed must be a whole number from 0 to ${0xffffffff}`);
if (!(mastery > 0 && mastery <= 1)) fail('--mastery must be a number in (0, 1]');
if (!existsSync(join(appDir, 'index.html')))
  fail(`no ${appDir}/index.html: run "npm run build:single" (or "npm run build" with --app dist) first`);

function walk(dir) {
  const files = {};
  for (const name of readdirSync(dir)) {
    const p = join(dir, name);
    if (statSync(p).isDirectory()) Object.assign(files, walk(p));
    else files[relative(appDir, p).split('\\').join('/')] = new Uint8Array(readFileSync(p));
  }
  return files;
}
const app = walk(appDir);
// the static build's service worker would cache the package inside the LMS; it is not needed there
for (const k of Object.keys(app)) if (/^(sw\.js|workbox-[^/]+\.js|registerSW\.js)$/.test(k)) delete app[k];

const vite = await createServer({
  configFile: false,
  logLevel: 'error',
  server: { middlewareMode: true, hmr: false, watch: null },
  appType: 'custom',
  optimizeDeps: { noDiscovery: true, include: [] },
});
try {
  const { parseQuestionList } = await vite.ssrLoadModule('/src/lms/grade.ts');
  const { buildPackages } = await vite.ssrLoadModule('/src/lms/packages.ts');
  const { katexMathml } = await vite.ssrLoadModule('/src/lms/mathml.ts');
  const questions = parseQuestionList(arg('questions', '1,2,3,4,5,6'));
  if (!questions) fail('--questions must list question numbers 1–6, e.g. 1,3,5');
  const version = JSON.parse(readFileSync('package.json', 'utf8')).version;
  const files = buildPackages({ questions, variants, seed, mastery, version }, app, katexMathml(katex));
  mkdirSync(out, { recursive: true });
  for (const [name, bytes] of Object.entries(files)) {
    writeFileSync(join(out, name), bytes);
    console.log(`${join(out, name).padEnd(34)} ${(bytes.length / 1e6).toFixed(2)} MB`);
  }
  console.log(
    `questions ${questions.join(',')}, ${variants} variant(s) each, seed ${seed}, mastery ${mastery}`,
  );
} finally {
  await vite.close();
}
