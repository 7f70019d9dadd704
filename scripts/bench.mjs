#!/usr/bin/env node
/**
 * `npm run bench`: performance numbers for the math core (not part of `npm test`).
 *
 * 1. `vitest bench --run` over bench/*.bench.ts, with --outputJson; every benchmark becomes a row
 *    with iterations/second and, when its group or name says "N samples|points|rays per
 *    iteration", samples/second.
 * 2. bench/runtimeError.ts, bundled with Vite (as the app is) and run in Node: RMSE and time per
 *    run against N for each estimator × sequence, and the exam-lobe kernel's samples/second.
 * 3. Where gcc exists: bench/c/exam_lobe.c compiled with `gcc -O2` and run on the same machine, for
 *    the batched-kernel-vs-C ratio (goal ≤ 1.3). Skipped, with a note, when gcc is absent.
 * Writes bench/results.json and prints a summary. Options: --quick (smaller sizes, for a smoke
 * test), --no-vitest (skip step 1).
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync, existsSync, readdirSync } from 'node:fs';
import { tmpdir, cpus, loadavg, totalmem } from 'node:os';
import { join, resolve, dirname } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const args = new Set(process.argv.slice(2));
const quick = args.has('--quick');
const tmp = mkdtempSync(join(tmpdir(), 'rml-bench-'));
const results = {
  generatedAt: new Date().toISOString(),
  quick,
  machine: {
    node: process.version,
    platform: `${process.platform} ${process.arch}`,
    cpu: cpus()[0]?.model ?? 'unknown',
    cpus: cpus().length,
    memoryGiB: +(totalmem() / 2 ** 30).toFixed(1),
    loadAverageAtStart: loadavg().map((x) => +x.toFixed(2)),
  },
  notes: [],
  vitest: [],
  examLobe: null,
  runtimeVsError: null,
};

function log(...a) {
  console.log(...a);
}

const PER_ITER =
  /(\d[\d_.,]*(?:e[+-]?\d+)?)\s*(?:samples|points|rays|estimates|lookups|evaluations)\s+per\s+iteration/i;
function perIteration(text) {
  const m = PER_ITER.exec(text);
  if (!m) return null;
  const v = Number(m[1].replace(/[_,]/g, ''));
  return Number.isFinite(v) && v > 0 ? v : null;
}

// ---------------------------------------------------------------- 1. vitest bench
try {
  if (args.has('--no-vitest')) {
    results.notes.push('vitest bench skipped (--no-vitest)');
  } else {
    const benchFiles = readdirSync(join(root, 'bench')).filter((f) => /\.bench\.ts$/.test(f));
    const jsonPath = join(tmp, 'vitest-bench.json');
    log(`▶ vitest bench over ${benchFiles.length} file(s): ${benchFiles.join(', ')}`);
    const r = spawnSync(
      'npx',
      ['vitest', 'bench', '--run', '--outputJson', jsonPath, ...benchFiles.map((f) => `bench/${f}`)],
      {
        cwd: root,
        stdio: ['ignore', 'inherit', 'inherit'],
        env: { ...process.env, FORCE_COLOR: '0' },
      },
    );
    if (!existsSync(jsonPath)) {
      results.notes.push(`vitest bench did not write a report (exit ${r.status})`);
    } else {
      const report = JSON.parse(readFileSync(jsonPath, 'utf8'));
      for (const file of report.files ?? []) {
        for (const group of file.groups ?? []) {
          for (const b of group.benchmarks ?? []) {
            const per = perIteration(b.name) ?? perIteration(group.fullName ?? '');
            results.vitest.push({
              file: file.filepath ? file.filepath.replace(root + '/', '') : null,
              group: (group.fullName ?? '').replace(/^.*?>\s*/, ''),
              name: b.name,
              iterationsPerSecond: b.hz,
              meanMs: b.mean,
              rmePercent: b.rme,
              iterations: b.sampleCount ?? null,
              samplesPerIteration: per,
              samplesPerSecond: per ? per * b.hz : null,
            });
          }
        }
      }
      if (r.status !== 0)
        results.notes.push(`vitest bench exited with status ${r.status}; partial results kept`);
    }
  }
} catch (e) {
  results.notes.push(`vitest bench failed: ${e.message}`);
}

// ---------------------------------------------------------------- 2 + 3. bundled runs and C
let mod = null;
try {
  log('▶ bundling bench/runtimeError.ts with Vite (as the app is built)');
  const { build } = await import('vite');
  await build({
    configFile: false,
    root,
    logLevel: 'error',
    ssr: { noExternal: true }, // bundle dependencies too, so the output runs from a temp folder
    build: {
      ssr: join(root, 'bench/runtimeError.ts'),
      outDir: tmp,
      emptyOutDir: false,
      minify: false,
      target: 'node20',
      rollupOptions: { output: { entryFileNames: 'runtimeError.mjs', format: 'es' } },
    },
  });
  mod = await import(pathToFileURL(join(tmp, 'runtimeError.mjs')).href);
} catch (e) {
  results.notes.push(`bundling bench/runtimeError.ts failed: ${e.stack ?? e.message}`);
}

// 3. exam-lobe kernel: JS (bundled) and C (gcc -O2), measured alternately so that both see the same
// machine load; best of all rounds for each.
try {
  const n = quick ? 200000 : 1000000;
  const rounds = quick ? 2 : 5;
  const reps = quick ? 3 : 5;
  let exe = null;
  let compiler = null;
  const gcc = spawnSync('gcc', ['--version'], { encoding: 'utf8' });
  if (gcc.error || gcc.status !== 0) {
    results.notes.push('gcc not found: C baseline skipped');
  } else {
    exe = join(tmp, 'exam_lobe');
    const cc = spawnSync('gcc', ['-O2', '-o', exe, join(root, 'bench/c/exam_lobe.c'), '-lm'], {
      encoding: 'utf8',
    });
    compiler = gcc.stdout.split('\n')[0];
    if (cc.status !== 0) {
      results.notes.push(`gcc failed, C baseline skipped: ${cc.stderr.trim().slice(0, 500)}`);
      exe = null;
    }
  }
  log(`▶ exam-lobe kernel: ${rounds} alternating rounds of JS (bundled) and C (gcc -O2), ${n} samples`);
  let js = null;
  let jsNaive = null;
  let c = null;
  for (let r = 0; r < rounds; r++) {
    if (mod) {
      const t = mod.timeExamLobe(n, reps);
      if (!js || t.batched.bestSeconds < js.bestSeconds) js = t.batched;
      if (!jsNaive || t.naive.bestSeconds < jsNaive.bestSeconds) jsNaive = t.naive;
    }
    if (exe) {
      const run = spawnSync(exe, [String(n), String(reps)], { encoding: 'utf8' });
      const t = JSON.parse(run.stdout);
      if (!c || t.bestSeconds < c.bestSeconds) c = { ...t, compiler, flags: '-O2' };
    }
  }
  results.examLobe = {
    js,
    jsNaive,
    c,
    cOverJs: js && c ? c.samplesPerSecond / js.samplesPerSecond : null,
    rounds,
    goal: 'C/JS ≤ 1.3 (batched JS within 1.3× of gcc -O2)',
  };
} catch (e) {
  results.notes.push(`exam-lobe timing failed: ${e.stack ?? e.message}`);
}

// 2. run time against error (after the kernel timing: see timeExamLobe's comment)
try {
  if (mod) {
    log('▶ run time vs error');
    const out = mod.main({ quick });
    results.runtimeVsError = { rows: out.rows, slopes: out.slopes };
  }
} catch (e) {
  results.notes.push(`run time vs error failed: ${e.stack ?? e.message}`);
}

rmSync(tmp, { recursive: true, force: true });
results.machine.loadAverageAtEnd = loadavg().map((x) => +x.toFixed(2));
writeFileSync(join(root, 'bench/results.json'), JSON.stringify(results, null, 2) + '\n');

// ---------------------------------------------------------------- summary
const fmt = (x) =>
  x == null
    ? '—'
    : x >= 1e6
      ? `${(x / 1e6).toFixed(2)} M`
      : x >= 1e3
        ? `${(x / 1e3).toFixed(1)} k`
        : x.toFixed(2);
log('\n== samples per second (vitest bench) ==');
for (const r of results.vitest)
  log(
    `${fmt(r.samplesPerSecond ?? r.iterationsPerSecond).padStart(10)}/s  ${r.samplesPerSecond ? '' : '(iterations) '}${r.group} › ${r.name}`,
  );
if (results.examLobe) {
  const e = results.examLobe;
  log('\n== exam-lobe kernel (bundled JS vs gcc -O2) ==');
  log(
    `JS batched ${fmt(e.js?.samplesPerSecond)}/s · JS naive ${fmt(e.jsNaive?.samplesPerSecond)}/s · C ${fmt(e.c?.samplesPerSecond)}/s` +
      (e.cOverJs ? ` · C/JS = ${e.cOverJs.toFixed(2)} (goal ≤ 1.3)` : ''),
  );
}
if (results.runtimeVsError) {
  log('\n== RMSE slope against N (log–log; −0.5 = plain Monte Carlo) ==');
  for (const s of results.runtimeVsError.slopes)
    log(`${s.slope.toFixed(2).padStart(6)}  ${s.problem} · ${s.estimator} · ${s.sequence}`);
}
for (const n of results.notes) log(`note: ${n}`);
log(`\nwrote bench/results.json`);
