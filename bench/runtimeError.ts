/**
 * Run time against error for the exam's estimators under each sample sequence, plus the
 * exam-lobe kernel timing used for the C comparison. Bundled by scripts/bench.mjs with the same
 * bundler as the app (so cross-module calls are inlined as in the browser) and run in Node.
 *
 * For each problem × estimator × sequence and each N in a doubling ladder, R independent runs
 * (seeds 1 … R) give R estimates; we record RMSE = √(mean (estimate − exact)²), the mean time
 * per run (sample generation + warp + sum), and the log–log slope of RMSE against N
 * (≈ −½ for independent sampling; steeper for stratified / QMC on smooth integrands).
 */
import { fillSequence1D, fillSequence2D, Rng, SEQUENCE_KINDS, type SequenceKind } from '../src/core/random';
import { sampleExamLobeBatch, examLobePdf, sampleUniformHemisphereBatch } from '../src/core/sampling';

export interface ErrorRow {
  problem: string;
  estimator: string;
  sequence: SequenceKind;
  n: number;
  runs: number;
  rmse: number;
  secondsPerRun: number;
}

export interface RuntimeErrorResult {
  rows: ErrorRow[];
  slopes: { problem: string; estimator: string; sequence: SequenceKind; slope: number }[];
}

type Estimator = {
  problem: string;
  name: string;
  dims: 1 | 2;
  exact: number;
  /** Estimate from n points of the sequence (u holds n or 2n values); scratch has ≥ 3n doubles. */
  run: (u: Float64Array, n: number, scratch: Float64Array) => number;
};

const K_EXAM = 2 / Math.expm1(2 * Math.PI);
const C_EXAM = Math.expm1(2 * Math.PI);

const ESTIMATORS: Estimator[] = [
  {
    problem: 'Q4: ∫₀² (x+2)² dx = 56/3',
    name: 'uniform p = 1/2',
    dims: 1,
    exact: 56 / 3,
    run: (u, n) => {
      let s = 0;
      for (let i = 0; i < n; i++) {
        const x = 2 * u[i];
        s += (x + 2) * (x + 2);
      }
      return (2 * s) / n;
    },
  },
  {
    problem: 'Q4: ∫₀² (x+2)² dx = 56/3',
    name: 'importance, linear p(x) = (x+1)/4',
    dims: 1,
    exact: 56 / 3,
    run: (u, n) => {
      // p(x) = (x + 1)/4 on [0, 2]; CDF (x² + 2x)/8 = ξ → x = −1 + √(1 + 8ξ)
      let s = 0;
      for (let i = 0; i < n; i++) {
        const x = -1 + Math.sqrt(1 + 8 * u[i]);
        s += ((x + 2) * (x + 2) * 4) / (x + 1);
      }
      return s / n;
    },
  },
  {
    problem: 'Q2: ∫_H cos θ dω = π',
    name: 'uniform hemisphere, 2π/N Σ f',
    dims: 2,
    exact: Math.PI,
    run: (u, n, w) => {
      sampleUniformHemisphereBatch(u, w, n);
      let s = 0;
      for (let i = 0; i < n; i++) s += w[3 * i + 2];
      return (2 * Math.PI * s) / n;
    },
  },
  {
    problem: 'Q2: ∫_H cos θ dω = π',
    name: 'importance, exam lobe k cos θ e^φ',
    dims: 2,
    exact: Math.PI,
    run: (u, n, w) => {
      sampleExamLobeBatch(u, w, n);
      let s = 0;
      for (let i = 0; i < n; i++) {
        const z = w[3 * i + 2];
        const p = examLobePdf(w[3 * i], w[3 * i + 1], z);
        if (p > 0) s += z / p;
      }
      return s / n;
    },
  },
];

function fitSlope(ns: number[], errs: number[]): number {
  const xs = ns.map(Math.log);
  const ys = errs.map((e) => Math.log(Math.max(e, 1e-300)));
  const mx = xs.reduce((a, b) => a + b, 0) / xs.length;
  const my = ys.reduce((a, b) => a + b, 0) / ys.length;
  let sxy = 0;
  let sxx = 0;
  for (let i = 0; i < xs.length; i++) {
    sxy += (xs[i] - mx) * (ys[i] - my);
    sxx += (xs[i] - mx) ** 2;
  }
  return sxy / sxx;
}

function timeBest(fn: () => void, reps: number): number {
  let best = Infinity;
  for (let r = 0; r < reps; r++) {
    const t0 = performance.now();
    fn();
    best = Math.min(best, performance.now() - t0);
  }
  return best / 1000;
}

export function main(opts: { quick?: boolean } = {}): RuntimeErrorResult {
  const ns = opts.quick ? [16, 64, 256, 1024] : [16, 64, 256, 1024, 4096, 16384];
  const runs = opts.quick ? 32 : 100;
  const maxN = ns[ns.length - 1];
  const u = new Float64Array(2 * maxN);
  const scratch = new Float64Array(3 * maxN);
  const rows: ErrorRow[] = [];
  const slopes: RuntimeErrorResult['slopes'] = [];
  for (const est of ESTIMATORS) {
    for (const seq of SEQUENCE_KINDS) {
      const errs: number[] = [];
      for (const n of ns) {
        let se = 0;
        const t0 = performance.now();
        for (let r = 1; r <= runs; r++) {
          if (est.dims === 1) fillSequence1D(seq, r, n, u);
          else fillSequence2D(seq, r, n, u);
          const e = est.run(u, n, scratch) - est.exact;
          se += e * e;
        }
        const secondsPerRun = (performance.now() - t0) / 1000 / runs;
        const rmse = Math.sqrt(se / runs);
        errs.push(rmse);
        rows.push({ problem: est.problem, estimator: est.name, sequence: seq, n, runs, rmse, secondsPerRun });
      }
      slopes.push({ problem: est.problem, estimator: est.name, sequence: seq, slope: fitSlope(ns, errs) });
    }
  }

  return { rows, slopes };
}

/**
 * Exam-lobe kernel timing: `sampleExamLobeBatch` (as shipped) on n samples, best of `reps`, and the
 * naive version (object per sample, key formulas). Call it first in a fresh process and, to be fair
 * on a loaded machine, alternately with the C baseline (scripts/bench.mjs does both): after
 * thousands of calls with tiny n (as in {@link main}'s loops) V8 kept a version of the kernel
 * that ran ~3× slower on 1e6 samples in our measurements.
 */
export function timeExamLobe(n: number, reps: number): { batched: KernelTiming; naive: KernelTiming } {
  if (!examInputs || examInputs.n !== n) {
    examInputs = { n, u: new Rng(1).fill(new Float64Array(2 * n)), out: new Float64Array(3 * n) };
  }
  const { u: uu, out } = examInputs;
  sampleExamLobeBatch(uu, out, n); // warm up
  const best = timeBest(() => sampleExamLobeBatch(uu, out, n), reps);
  let sink = 0;
  const naive = () => {
    const res: { x: number; y: number; z: number }[] = [];
    for (let i = 0; i < n; i++) {
      const theta = 0.5 * Math.acos(1 - 2 * uu[2 * i]);
      const phi = Math.log(C_EXAM * uu[2 * i + 1] + 1);
      res.push({
        x: Math.sin(theta) * Math.cos(phi),
        y: Math.sin(theta) * Math.sin(phi),
        z: Math.cos(theta),
      });
    }
    sink += res[n - 1].z * K_EXAM;
  };
  const naiveReps = Math.max(2, reps >> 1);
  const bestNaive = timeBest(naive, naiveReps);
  if (sink === 12345) console.log(''); // keep the naive result alive
  return {
    batched: { n, reps, bestSeconds: best, samplesPerSecond: n / best },
    naive: { n, reps: naiveReps, bestSeconds: bestNaive, samplesPerSecond: n / bestNaive },
  };
}

/** Best-of-reps timing of one kernel over n samples. */
export interface KernelTiming {
  n: number;
  reps: number;
  bestSeconds: number;
  samplesPerSecond: number;
}

let examInputs: { n: number; u: Float64Array; out: Float64Array } | null = null;
