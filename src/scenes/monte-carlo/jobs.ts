/**
 * The long computations of the Monte Carlo scene, written as plain async functions of plain data so
 * they run in the worker (mc.worker.ts) and in unit tests alike. They report partial results at a
 * steady rate (every ~`every` ms, not per sample) and yield to the event loop between batches.
 */
import {
  ConvergenceRun1D,
  estimate1D,
  logSpacedCounts,
  RmseAccumulator,
  fitLogLogSlope,
  type McEstimate,
} from '../../core/estimators';
import { fail, raise, type Failure } from '../../core/failure';
import type { ProgressFn } from '../../workers/protocol';
import type { Pdf1D } from '../../core/sampling/pdf1d';
import { runSeed } from '../../core/random/rng';
import { checkLimits, exactIntegral, type Fn1 } from './integral';
import { choosePdf, type PdfChoice } from './pdfChoice';
import type { PdfKind, Strategy } from './params';

/** Compiles a user expression in x (the worker passes core/expr's compiler). */
export type Compile = (src: string) => Promise<{ ok: true; fn: Fn1; tex?: string } | Failure>;

/** The problem as plain data (what the page sends to the worker). */
export interface ProblemArgs {
  f: string;
  a: number;
  b: number;
  pdfexpr: string;
  seed: number;
  strategies: { pdf: PdfKind; seq: Strategy; label: string }[];
}

export interface Prepared {
  f: Fn1;
  exact: number;
  samplers: (Pdf1D | null)[];
  /** Strategies left out, each with why (the pdf's own Failure, its message led by the label). */
  problems: Failure[];
}

/** Compile f (and the custom pdf if used), compute the reference, build every strategy's sampler. */
export async function prepare(args: ProblemArgs, compile: Compile): Promise<Prepared> {
  const cf = await compile(args.f);
  if (!cf.ok) raise(fail(cf.kind, `f: ${cf.message}`));
  const { a, b } = checkLimits(args.a, args.b);
  let custom: Fn1 | null = null;
  if (args.strategies.some((s) => s.pdf === 'custom')) {
    const cp = await compile(args.pdfexpr);
    if (cp.ok) custom = cp.fn;
  }
  const ex = exactIntegral(args.f, cf.fn, a, b);
  const cache = new Map<PdfKind, PdfChoice>();
  const problems: Failure[] = [];
  const samplers = args.strategies.map((s) => {
    let c = cache.get(s.pdf);
    if (!c) {
      c = choosePdf(s.pdf, args.f, cf.fn, a, b, custom);
      cache.set(s.pdf, c);
    }
    if (!c.ok) {
      problems.push(fail(c.kind, `${s.label}: ${c.message}`));
      return null;
    }
    return c.sampler;
  });
  return { f: cf.fn, exact: ex.value, samplers, problems };
}

/** Per-strategy convergence data of one run. */
export interface SeriesData {
  label: string;
  n: Float64Array;
  estimate: Float64Array;
  absError: Float64Array;
  stderr: Float64Array;
  recorded: number;
  slope: number;
}

type Progress<P = unknown> = ProgressFn<P>;

/** What a convergence run reports as it goes (and returns at the end). */
export interface ConvergencePartial {
  series: SeriesData[];
  exact: number;
  problems: Failure[];
}
const now = (): number => (typeof performance !== 'undefined' ? performance.now() : Date.now());
const tick = (): Promise<void> => new Promise((r) => setTimeout(r, 0));

/**
 * One convergence run per strategy up to nMax samples, recorded at log-spaced N (10 per decade).
 * Strategies advance together (round robin), so every curve grows as the run proceeds.
 */
export async function convergenceJob(
  args: ProblemArgs & { nMax: number },
  compile: Compile,
  progress: Progress<ConvergencePartial> = () => {},
  every = 250,
) {
  const prep = await prepare(args, compile);
  const cps = logSpacedCounts(args.nMax, 10);
  const runs = args.strategies.map((s, i) =>
    prep.samplers[i]
      ? new ConvergenceRun1D(
          { f: prep.f, pdf: prep.samplers[i], sequence: s.seq, seed: args.seed },
          cps,
          prep.exact,
        )
      : null,
  );
  const total = runs.reduce((t, r) => t + (r ? r.total : 0), 0) || 1;
  const snapshot = (): SeriesData[] =>
    runs.map((r, i) => {
      const label = args.strategies[i].label;
      if (!r)
        return {
          label,
          n: cps.slice(0, 0),
          estimate: new Float64Array(0),
          absError: new Float64Array(0),
          stderr: new Float64Array(0),
          recorded: 0,
          slope: NaN,
        };
      const k = r.series.recorded;
      const s = r.series;
      const fit = fitLogLogSlope(s.n, s.absError, 0, k);
      return {
        label,
        n: s.n.slice(0, k),
        estimate: s.estimate.slice(0, k),
        absError: s.absError.slice(0, k),
        stderr: s.stderr.slice(0, k),
        recorded: k,
        slope: fit.slope,
      };
    });
  let last = now();
  let pending = true;
  while (pending) {
    pending = false;
    for (const r of runs) if (r && !r.step(32768)) pending = true;
    if (now() - last > every) {
      const done = runs.reduce((t, r) => t + (r ? r.done : 0), 0);
      progress(done / total, { series: snapshot(), exact: prep.exact, problems: prep.problems });
      last = now();
      await tick();
    }
  }
  return { series: snapshot(), exact: prep.exact, problems: prep.problems };
}

/** RMSE summary per strategy. */
export interface RmseData {
  label: string;
  n: Float64Array;
  rmse: Float64Array;
  lo: Float64Array;
  hi: Float64Array;
  /** Wall-clock time (ms) of one estimate with n[k] samples: n[k] × the measured cost per sample. */
  timeMs: Float64Array;
  slope: number;
  runs: number;
}

/** The RMSE of the first strategy at exactly n samples (null until the run has reached n). */
export function rmseAt(rmse: RmseData[] | undefined, n: number): number | null {
  const r = rmse?.[0];
  if (!r || r.n.length === 0) return null;
  const k = r.n.length - 1;
  return r.n[k] === n ? r.rmse[k] : null;
}

/**
 * RMSE over `runs` independent runs (seeds runSeed(seed, r)) at log-spaced N up to nMax (4 per
 * decade), with the 10–90 % band of |error|, and the time of an N-sample estimate = N × the cost
 * per sample measured in this thread with performance.now() over all runs (the cost per sample of a
 * run to N_max; setup such as tabulating a pdf is not counted).
 */
export async function rmseJob(
  args: ProblemArgs & { nMax: number; runs: number },
  compile: Compile,
  progress: Progress<{ rmse: RmseData[] }> = () => {},
  every = 250,
) {
  const prep = await prepare(args, compile);
  const cps = logSpacedCounts(args.nMax, 4, 10);
  const S = args.strategies.length;
  const accs = args.strategies.map(() => new RmseAccumulator(cps, prep.exact, args.runs));
  // measured cost: total time and total samples per strategy (performance.now() is coarse, ~0.1 ms
  // in browsers, so per-checkpoint timings of small N would be noise; the cost per sample is not)
  const totalMs = new Float64Array(S);
  const totalSamples = new Float64Array(S);
  const snapshot = (): RmseData[] =>
    args.strategies.map((s, i) => {
      const acc = accs[i];
      const sum = acc.summary(0.1, 0.9);
      const perSample = totalSamples[i] > 0 ? totalMs[i] / totalSamples[i] : NaN;
      const t = sum.n.map((n) => n * perSample);
      return {
        label: s.label,
        n: sum.n,
        rmse: sum.rmse,
        lo: sum.lo,
        hi: sum.hi,
        timeMs: t,
        slope: fitLogLogSlope(sum.n, sum.rmse).slope,
        runs: acc.runs,
      };
    });
  let last = now();
  const totalWork = args.runs * S;
  let work = 0;
  for (let r = 0; r < args.runs; r++) {
    for (let i = 0; i < S; i++) {
      work++;
      const sampler = prep.samplers[i];
      if (!sampler) continue;
      const seq = args.strategies[i].seq;
      const run = new ConvergenceRun1D(
        { f: prep.f, pdf: sampler, sequence: seq, seed: runSeed(args.seed, r) },
        cps,
        prep.exact,
      );
      const t0 = now();
      for (let k = 0; k < cps.length; k++) {
        // advance exactly to checkpoint k: progressive sequences continue, stratified starts a new set
        const budget = seq === 'stratified' ? cps[k] : cps[k] - (k ? cps[k - 1] : 0);
        run.step(budget);
      }
      totalMs[i] += now() - t0;
      totalSamples[i] += run.total;
      if (now() - last > every) {
        progress(work / totalWork, { rmse: snapshot() });
        last = now();
        await tick();
      }
      accs[i].addRun(run.series);
    }
  }
  return { rmse: snapshot(), exact: prep.exact, problems: prep.problems };
}

/**
 * Unbiasedness: M independent estimates, each with N samples, for one strategy. Returns the
 * estimates (Float64Array of length M, transferred).
 */
export async function histogramJob(
  args: ProblemArgs & { N: number; M: number },
  compile: Compile,
  progress: Progress<{ estimates: Float64Array }> = () => {},
  every = 250,
) {
  const prep = await prepare(args, compile);
  const sampler = prep.samplers[0];
  if (!sampler) raise(prep.problems[0] ?? fail('no-pdf', 'no usable pdf'));
  const seq = args.strategies[0].seq;
  const out = new Float64Array(args.M).fill(NaN);
  let last = now();
  for (let m = 0; m < args.M; m++) {
    out[m] = estimate1D(
      { f: prep.f, pdf: sampler, sequence: seq, seed: runSeed(args.seed ^ 0x5bd1e995, m) },
      args.N,
    ).estimate;
    if (now() - last > every) {
      progress(m / args.M, { estimates: out.slice(0, m + 1) });
      last = now();
      await tick();
    }
  }
  return { estimates: out, exact: prep.exact };
}

/** One estimate with n drawn samples (large n: runs here, in batches, with progress). */
export async function estimateJob(
  args: ProblemArgs & { n: number },
  compile: Compile,
  progress: Progress = () => {},
): Promise<McEstimate & { ms: number }> {
  const prep = await prepare(args, compile);
  const sampler = prep.samplers[0];
  if (!sampler) raise(prep.problems[0] ?? fail('no-pdf', 'no usable pdf'));
  const seq = args.strategies[0].seq;
  // one run to N with a single checkpoint: same numbers as estimate1D, but resumable
  const run = new ConvergenceRun1D(
    { f: prep.f, pdf: sampler, sequence: seq, seed: args.seed },
    [args.n],
    prep.exact,
  );
  const t0 = now();
  while (!run.step(262144)) {
    progress(run.done / run.total);
    await tick();
  }
  const ms = now() - t0;
  const s = run.series;
  return {
    n: args.n - s.invalid,
    estimate: s.estimate[0],
    variance: NaN,
    stderr: s.stderr[0],
    invalid: s.invalid,
    ms,
  };
}
