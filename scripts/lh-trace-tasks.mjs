#!/usr/bin/env node
/**
 * The long tasks of the trace Lighthouse simulated from (`PERF_TRACE=t.json npm run perf …` writes
 * it), each with its wall time (what Lighthouse counts) against its CPU time, and what ran inside;
 * and the busy time of every thread. A task whose wall time is many times its CPU time waited for
 * the cores: look at the threads list for what competed (a service worker's precache, workers).
 *
 * --threads: beside each long task, the other threads that ran during it (a worker's script is
 * named), i.e. who had the cores. --forced: every style recalculation or layout of over 1 ms that
 * JavaScript forced (a getComputedStyle, offsetWidth… while the page was changing), with the
 * script position that asked for it.
 *
 *   node scripts/lh-trace-tasks.mjs t.json [--min 20] [--threads] [--forced]
 */
import { readFileSync } from 'node:fs';

const args = process.argv.slice(2);
const mi = args.indexOf('--min');
const min = mi >= 0 ? Number(args.splice(mi, 2)[1]) : 20;
const flag = (name) => {
  const i = args.indexOf(name);
  if (i >= 0) args.splice(i, 1);
  return i >= 0;
};
const withThreads = flag('--threads');
const withForced = flag('--forced');
const { traceEvents: ev } = JSON.parse(readFileSync(args[0], 'utf8'));
const key = (e) => `${e.pid}:${e.tid}`;
const names = new Map();
for (const e of ev) if (e.name === 'thread_name') names.set(key(e), e.args.name);
const isTask = (e) => e.ph === 'X' && (e.name === 'RunTask' || e.name === 'ThreadControllerImpl::RunTask');
const busy = new Map();
for (const e of ev) if (isTask(e)) busy.set(key(e), (busy.get(key(e)) ?? 0) + e.dur / 1000);
// the page's main thread: the busiest CrRendererMain
const main = [...busy].filter(([k]) => names.get(k) === 'CrRendererMain').sort((a, b) => b[1] - a[1])[0][0];
console.log('busy time per thread (ms, wall):');
for (const [k, v] of [...busy].sort((a, b) => b[1] - a[1]).slice(0, 10))
  console.log(`  ${v.toFixed(0).padStart(6)}  ${names.get(k) ?? '?'}${k === main ? ' (the page)' : ''}`);
const xs = ev
  .filter((e) => key(e) === main && e.ph === 'X' && e.dur !== undefined)
  .sort((a, b) => a.ts - b.ts);
const others = withThreads ? ev.filter((e) => isTask(e) && key(e) !== main) : [];
// a dedicated worker's script: the first URL its thread mentions
const workerScript = new Map();
for (const e of withThreads ? ev : []) {
  const u = e.args?.data?.url;
  if (u && names.get(key(e)) === 'DedicatedWorker thread' && !workerScript.has(key(e)))
    workerScript.set(key(e), String(u).split('/').pop());
}
const t0 = xs[0]?.ts ?? 0;
const INSIDE =
  /^(FunctionCall|EvaluateScript|v8\.compile|v8\.compileModule|v8\.evaluateModule|Layout|UpdateLayoutTree|Paint|PrePaint|Commit|ParseHTML|MinorGC|MajorGC|RunMicrotasks|TimerFire|FireAnimationFrame|EventDispatch|HitTest)$/;
let until = -Infinity;
console.log(`\ntasks over ${min} ms wall (start, wall, CPU, inside):`);
for (const t of xs) {
  if (!isTask(t) || t.ts < until) continue;
  until = t.ts + t.dur;
  if (t.dur / 1000 < min) continue;
  const agg = new Map();
  for (const e of xs) {
    if (e === t || e.ts < t.ts || e.ts + e.dur > until || !INSIDE.test(e.name)) continue;
    const d = e.args?.data ?? {};
    const k =
      e.name === 'FunctionCall'
        ? `js ${d.functionName || '(anon)'} ${String(d.url ?? '')
            .split('/')
            .pop()}`
        : e.name;
    agg.set(k, (agg.get(k) ?? 0) + e.dur / 1000);
  }
  const top = [...agg]
    .sort((a, b) => b[1] - a[1])
    .slice(0, 5)
    .map(([k, v]) => `${k} ${v.toFixed(1)}`)
    .join(' | ');
  console.log(
    `${((t.ts - t0) / 1000).toFixed(0).padStart(7)} ms  ${(t.dur / 1000).toFixed(1).padStart(6)}  ${((t.tdur ?? t.dur) / 1000).toFixed(1).padStart(6)}  ${top}`,
  );
  if (withThreads) {
    const other = new Map();
    for (const e of others) {
      const o = Math.min(until, e.ts + e.dur) - Math.max(t.ts, e.ts);
      if (o > 0) other.set(key(e), (other.get(key(e)) ?? 0) + o / 1000);
    }
    const list = [...other]
      .sort((a, b) => b[1] - a[1])
      .slice(0, 5)
      .map(
        ([k, v]) =>
          `${names.get(k) ?? '?'}${workerScript.has(k) ? ` (${workerScript.get(k)})` : ''} ${v.toFixed(0)}`,
      );
    console.log(`${' '.repeat(26)}meanwhile: ${list.join(', ') || 'nothing'}`);
  }
}

if (withForced) {
  console.log('\nstyle and layout forced by JavaScript (start, kind, ms, asked from):');
  const js = xs.filter(
    (e) =>
      e.name === 'FunctionCall' ||
      e.name === 'EvaluateScript' ||
      e.name === 'v8.callFunction' ||
      e.name === 'TimerFire' ||
      e.name === 'FireAnimationFrame',
  );
  for (const e of xs) {
    if ((e.name !== 'UpdateLayoutTree' && e.name !== 'Layout') || e.dur < 1000) continue;
    if (!js.some((f) => f.ts <= e.ts && f.ts + f.dur >= e.ts + e.dur)) continue;
    const st = e.args?.beginData?.stackTrace ?? e.args?.data?.stackTrace ?? [];
    const at = st
      .slice(0, 3)
      .map(
        (f) =>
          `${f.functionName || '(anon)'} ${String(f.url).split('/').pop()}:${f.lineNumber}:${f.columnNumber}`,
      )
      .join(' < ');
    console.log(
      `${((e.ts - t0) / 1000).toFixed(0).padStart(7)} ms  ${e.name.padEnd(16)} ${(e.dur / 1000).toFixed(1).padStart(6)}  ${at || '(no stack)'}`,
    );
  }
}
