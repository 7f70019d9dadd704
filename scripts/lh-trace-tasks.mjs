#!/usr/bin/env node
/**
 * The long tasks of the trace Lighthouse simulated from (`PERF_TRACE=t.json npm run perf …` writes
 * it), each with its wall time (what Lighthouse counts) against its CPU time, and what ran inside;
 * and the busy time of every thread. A task whose wall time is many times its CPU time waited for
 * the cores: look at the threads list for what competed (a service worker's precache, workers).
 *
 *   node scripts/lh-trace-tasks.mjs t.json [--min 20]
 */
import { readFileSync } from 'node:fs';

const args = process.argv.slice(2);
const mi = args.indexOf('--min');
const min = mi >= 0 ? Number(args.splice(mi, 2)[1]) : 20;
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
for (const [k, v] of [...busy].sort((a, b) => b[1] - a[1]).slice(0, 10)) console.log(`  ${v.toFixed(0).padStart(6)}  ${names.get(k) ?? '?'}${k === main ? ' (the page)' : ''}`);
const xs = ev.filter((e) => key(e) === main && e.ph === 'X' && e.dur !== undefined).sort((a, b) => a.ts - b.ts);
const t0 = xs[0]?.ts ?? 0;
const INSIDE = /^(FunctionCall|EvaluateScript|v8\.compile|v8\.compileModule|v8\.evaluateModule|Layout|UpdateLayoutTree|Paint|PrePaint|Commit|ParseHTML|MinorGC|MajorGC|RunMicrotasks|TimerFire|FireAnimationFrame|EventDispatch|HitTest)$/;
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
    const k = e.name === 'FunctionCall' ? `js ${d.functionName || '(anon)'} ${String(d.url ?? '').split('/').pop()}` : e.name;
    agg.set(k, (agg.get(k) ?? 0) + e.dur / 1000);
  }
  const top = [...agg].sort((a, b) => b[1] - a[1]).slice(0, 5).map(([k, v]) => `${k} ${v.toFixed(1)}`).join(' | ');
  console.log(`${((t.ts - t0) / 1000).toFixed(0).padStart(7)} ms  ${(t.dur / 1000).toFixed(1).padStart(6)}  ${((t.tdur ?? t.dur) / 1000).toFixed(1).padStart(6)}  ${top}`);
}
