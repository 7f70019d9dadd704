/**
 * Shared by the diagnostic profilers (scripts/profile-load.mjs, scripts/profile-anim.mjs): option
 * parsing, serving the built app, and summing a CDP CPU profile by script, by function (self time)
 * and by inclusive time within the app's own scripts.
 */
import { spawn } from 'node:child_process';

/** Remove `--name value` from args and return the value (or `def`). */
export function takeOpt(args, name, def) {
  const i = args.indexOf(name);
  if (i < 0) return def;
  const v = args[i + 1];
  args.splice(i, 2);
  return v;
}

/** Serve `dist` under /app/ on 127.0.0.1:port (scripts/serve.mjs); resolves once it listens. */
export async function serveDist(dist, port) {
  const server = spawn(process.execPath, ['scripts/serve.mjs', dist, String(port)], {
    stdio: ['ignore', 'pipe', 'inherit'],
  });
  await new Promise((r) => server.stdout.once('data', r));
  return server;
}

const isIdle = (cf) => cf.functionName === '(idle)' || cf.functionName === '(program)';
const short = (url) => url.replace(/^.*\/assets\//, '').replace(/^.*\/app\//, '');
const key = (cf) => `${cf.functionName || '(anon)'}  ${short(cf.url)}:${cf.lineNumber + 1}`;

/** Index a profile: nodes by id, each node's parent, and the (node id, ms) of every sample. */
export function indexProfile(profile) {
  const nodes = new Map(profile.nodes.map((n) => [n.id, n]));
  const parent = new Map();
  for (const n of profile.nodes) for (const c of n.children ?? []) parent.set(c, n.id);
  const samples = profile.samples.map((id, i) => [id, (profile.timeDeltas[i + 1] ?? 0) / 1000]);
  return { nodes, parent, samples };
}

/** Inclusive time per app-script function over the given samples (each function once per sample). */
export function inclusive(ix, samples) {
  const incl = new Map();
  for (const [id, t] of samples) {
    const seen = new Set();
    for (let x = id; x !== undefined; x = ix.parent.get(x)) {
      const cf = ix.nodes.get(x).callFrame;
      if (!cf.url.includes('/assets/')) continue;
      const k = key(cf);
      if (seen.has(k)) continue;
      seen.add(k);
      incl.set(k, (incl.get(k) ?? 0) + t);
    }
  }
  return incl;
}

const print = (title, map, n) => {
  if (n <= 0) return;
  console.log(title);
  for (const [k, v] of [...map].sort((a, b) => b[1] - a[1]).slice(0, n))
    console.log(`${v.toFixed(0).padStart(7)} ms  ${k}`);
};

/** Print busy time by script, by function (self) and, if `withInclusive`, inclusive; returns the busy ms. */
export function summarize(profile, { top = 25, withInclusive = false } = {}) {
  const ix = indexProfile(profile);
  const byFn = new Map();
  const byUrl = new Map();
  let total = 0;
  for (const [id, t] of ix.samples) {
    const cf = ix.nodes.get(id).callFrame;
    if (isIdle(cf)) continue;
    total += t;
    byFn.set(key(cf), (byFn.get(key(cf)) ?? 0) + t);
    const u = short(cf.url) || cf.functionName;
    byUrl.set(u, (byUrl.get(u) ?? 0) + t);
  }
  return {
    total,
    ix,
    print() {
      print('-- by script', byUrl, 12);
      print('-- by function (self)', byFn, top);
      if (withInclusive)
        print(
          '-- inclusive (app scripts)',
          inclusive(
            ix,
            ix.samples.filter(([id]) => !isIdle(ix.nodes.get(id).callFrame)),
          ),
          top,
        );
    },
  };
}

export { print as printTop };

/**
 * The JavaScript samples of one thread (`pid:tid`) in a Chromium trace recorded with the
 * `disabled-by-default-v8.cpu_profiler` category: the profile's nodes by id, and [time µs, node id]
 * of every sample (its ProfileChunk events, in order).
 */
export function traceProfileSamples(events, thread) {
  const nodes = new Map();
  const samples = [];
  const prof = events.find((e) => e.name === 'Profile' && `${e.pid}:${e.tid}` === thread);
  let clock = prof?.args?.data?.startTime ?? 0;
  for (const e of events) {
    if (e.name !== 'ProfileChunk' || !prof || e.pid !== prof.pid || e.id !== prof.id) continue;
    const d = e.args.data;
    for (const n of d.cpuProfile?.nodes ?? []) nodes.set(n.id, n);
    const ids = d.cpuProfile?.samples ?? [];
    const deltas = d.timeDeltas ?? [];
    for (let i = 0; i < ids.length; i++) {
      clock += deltas[i] ?? 0;
      samples.push([clock, ids[i]]);
    }
  }
  return { nodes, samples };
}

/** The phone the load diagnostics emulate (Lighthouse's mobile screen; no service worker). */
export const PHONE_CONTEXT = {
  viewport: { width: 412, height: 823 },
  deviceScaleFactor: 1.75,
  isMobile: true,
  hasTouch: true,
  serviceWorkers: 'block',
};
