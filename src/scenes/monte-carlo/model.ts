/**
 * Model of the Monte Carlo scene: pure functions of the parameters (and of the compiled integrand
 * and pdf expressions), calling the core. Nothing here knows about React, Plotly or workers.
 */
import {
  estimate1D,
  importanceEstimate,
  uniformEstimate,
  type McEstimate,
  type Problem1D,
} from '../../core/estimators';
import { integrate1D, INTEGRATION_METHOD } from '../../core/verify/integrate1d';
import {
  customPdf1D,
  linearPdf1D,
  proportionalPdf1D,
  squarePdf1D,
  uniformPdf1D,
  type Pdf1D,
} from '../../core/sampling/pdf1d';
import { fail, type Failure } from '../../core/failure';
import { Rng } from '../../core/random/rng';
import { RACE_SAMPLES, type PdfKind, type Strategy } from './params';

/** The exam's four samples (Q4(b)). */
export const EXAM_SAMPLES: readonly number[] = [1.16, 1.98, 0.54, 1.26];
/** The exam's integrand and limits. */
export const EXAM_F = '(x+2)^2';
export const EXAM_A = 0;
export const EXAM_B = 2;
/**
 * Figures as PRINTED in the answer key for Q4(b) (not used for any computation: only to say where
 * the live computation differs from what the key prints).
 */
export const KEY_PRINTED = { f: [9.98, 18.84, 6.45, 10.26], estimate: 21.45 } as const;

/** A real function of x (compiled user expression or closed form). */
export type Fn1 = (x: number) => number;

/** Default limits used when the URL's are unusable. */
export function checkLimits(a: number, b: number): { a: number; b: number; message: string | null } {
  if (Number.isFinite(a) && Number.isFinite(b) && a < b) return { a, b, message: null };
  return {
    a: EXAM_A,
    b: EXAM_B,
    message: `The limits must satisfy a < b (got a = ${a}, b = ${b}); using [${EXAM_A}, ${EXAM_B}].`,
  };
}

/**
 * If the source is (x + c)^2 (spaces, ** and a leading + ignored), return c, else null: then p ∝ f
 * has the closed form p = 3(x + c)²/((b + c)³ − (a + c)³) and the integral is exact.
 */
export function squareShift(src: string): number | null {
  const s = src.replace(/\s+/g, '').replace(/\*\*/g, '^');
  const m = /^\(x([+-])(\d+(?:\.\d*)?(?:e[+-]?\d+)?)\)\^2$/i.exec(s);
  if (m) {
    const c = Number(m[2]);
    return Number.isFinite(c) ? (m[1] === '-' ? -c : c) : null;
  }
  if (s === 'x^2') return 0;
  return null;
}

/** Reference value of ∫ₐᵇ f dx with the method that produced it. */
export interface Exact {
  value: number;
  /** Method, named for the page. */
  method: string;
  /** Estimated absolute error of `value` (0 for closed forms). */
  error: number;
  /** Why there is no value (non-finite f, divergent integral). */
  problem: string | null;
}

/**
 * ∫ₐᵇ f dx: closed form ((b + c)³ − (a + c)³)/3 when f is (x + c)², else adaptive Gauss–Kronrod
 * to full precision (core/verify/integrate1d).
 */
export function exactIntegral(fSrc: string, f: Fn1, a: number, b: number): Exact {
  const c = squareShift(fSrc);
  if (c !== null) {
    const A = a + c;
    const B = b + c;
    return {
      value: ((b - a) * (B * B + A * B + A * A)) / 3,
      method: 'closed form ((b + c)³ − (a + c)³)/3',
      error: 0,
      problem: null,
    };
  }
  const r = integrate1D(f, a, b);
  if (r.nonFiniteAt !== undefined) {
    return {
      value: NaN,
      method: INTEGRATION_METHOD,
      error: Infinity,
      problem: `f is not finite at x = ${fmt(r.nonFiniteAt)}, so ∫ f dx has no value on [${fmt(a)}, ${fmt(b)}].`,
    };
  }
  if (!r.converged) {
    return {
      value: NaN,
      method: INTEGRATION_METHOD,
      error: r.error,
      problem: `∫ f dx over [${fmt(a)}, ${fmt(b)}] does not converge (the quadrature error does not shrink): the integral may diverge.`,
    };
  }
  return {
    value: r.value,
    method: `${INTEGRATION_METHOD}, ${r.evaluations} evaluations, error ≤ ${r.error.toExponential(1)}`,
    error: r.error,
    problem: null,
  };
}

/** A usable sampling density for the scene, or the reason it cannot be used. */
export type PdfChoice =
  | {
      ok: true;
      kind: PdfKind;
      /** Sampler (for drawn samples): its pdf is the density the samples really have. */
      sampler: Pdf1D;
      /** The exact normalized density, used for given samples and the drawn curve. */
      density: Fn1;
      /** Human description, e.g. "p(x) = 3(x + 2)²/56 (closed form)". */
      label: string;
      /** A note (e.g. the tabulation, or a fallback). */
      note: string | null;
    }
  | Failure<PdfKind>;

const fmt = (x: number): string => (Number.isInteger(x) ? String(x) : Number(x.toPrecision(6)).toString());

/**
 * Build the chosen pdf on [a, b] for the integrand f:
 * - uniform: 1/(b − a);
 * - linear: the ramp through |f(a)| and |f(b)| (core `linearPdf1D`);
 * - proportional: p ∝ f, in closed form when f is (x + c)², else tabulated p ∝ |f| (4096 bins);
 * - custom: the typed pdf, validated and normalized (core `customPdf1D`).
 */
export function choosePdf(
  kind: PdfKind,
  fSrc: string,
  f: Fn1,
  a: number,
  b: number,
  custom: Fn1 | null,
): PdfChoice {
  switch (kind) {
    case 'uniform': {
      const s = uniformPdf1D(a, b);
      return {
        ok: true,
        kind,
        sampler: s,
        density: s.pdf,
        label: `p(x) = 1/(b − a) = ${fmt(1 / (b - a))}`,
        note: null,
      };
    }
    case 'linear': {
      const w0 = Math.abs(f(a));
      const w1 = Math.abs(f(b));
      if (!(Number.isFinite(w0) && Number.isFinite(w1) && w0 + w1 > 0)) {
        return {
          ok: false,
          kind,
          message: `The linear pdf is the ramp through |f(a)| and |f(b)|, but these are ${fmt(w0)} and ${fmt(w1)}: no ramp to sample. Choose another pdf.`,
        };
      }
      const s = linearPdf1D(a, b, w0, w1);
      return {
        ok: true,
        kind,
        sampler: s,
        density: s.pdf,
        label: `p(x) ∝ ramp from |f(a)| = ${fmt(w0)} to |f(b)| = ${fmt(w1)}`,
        note: null,
      };
    }
    case 'proportional': {
      const c = squareShift(fSrc);
      if (c !== null) {
        const s = squarePdf1D(a, b, c);
        const A = a + c;
        const B = b + c;
        const D = (b - a) * (B * B + A * B + A * A);
        const cs = c === 0 ? 'x' : `x ${c > 0 ? '+' : '−'} ${fmt(Math.abs(c))}`;
        return {
          ok: true,
          kind,
          sampler: s,
          density: s.pdf,
          label: `p(x) = 3(${cs})²/${fmt(D)} (closed form, inverted by a cube root)`,
          note: null,
        };
      }
      const r = proportionalPdf1D(f, a, b);
      if (!r.ok) return { ok: false, kind, message: `p ∝ |f| cannot be built: ${r.message}` };
      return {
        ok: true,
        kind,
        sampler: r.pdf,
        density: r.density,
        label: `p(x) = |f(x)| / ${fmt(r.norm)}`,
        note: 'Samples are drawn from a 4096-bin table of |f| (each bin holds the exact mass of |f| over it); the estimator divides by the tabulated density, which the samples really follow, so it stays unbiased.',
      };
    }
    case 'custom': {
      if (!custom) return { ok: false, kind, message: 'Type a pdf p(x) for the custom strategy.' };
      const r = customPdf1D(custom, a, b, f);
      if (!r.ok) return { ok: false, kind, message: `This pdf cannot be used: ${r.message}` };
      return {
        ok: true,
        kind,
        sampler: r.pdf,
        density: r.density,
        label: `p(x) = your expression / ${fmt(r.norm)} (normalized numerically)`,
        note: 'Samples are drawn from a 4096-bin table of your pdf (exact bin masses); the estimator divides by that tabulated density, so it stays unbiased.',
      };
    }
  }
}

/** One row of the worked table. */
export interface SampleRow {
  x: number;
  f: number;
  p: number;
  /** f/p (NaN when p = 0 and f ≠ 0). */
  ratio: number;
  /** Uniform term (b − a) f(x). */
  uniformTerm: number;
  /** Importance term f/p with p ∝ |f| (exact density); NaN when there is none. */
  propRatio: number;
  /** Outside [a, b]? */
  outside: boolean;
}

/** The worked Q4 table for given samples: rows and the three estimates. */
export interface SampleTable {
  rows: SampleRow[];
  /** Estimator with the chosen pdf (importance; for the uniform pdf it is the uniform estimator). */
  chosen: McEstimate | null;
  /** Uniform estimator (b − a)/N Σ f(xᵢ). */
  uniform: McEstimate;
  /** Importance estimator with p ∝ |f| (exact density). */
  proportional: McEstimate | null;
  /** Problems with the given samples: kind 'outside' ([a, b]) or 'zero-pdf' (p = 0 where f ≠ 0). */
  problems: Failure[];
}

/** Build the worked table for the samples xs (given, or the exam's four). */
export function sampleTable(
  xs: readonly number[],
  f: Fn1,
  a: number,
  b: number,
  density: Fn1 | null,
  propDensity: Fn1 | null,
): SampleTable {
  const problems: Failure[] = [];
  const rows: SampleRow[] = xs.map((x) => {
    const fx = f(x);
    const outside = !(x >= a && x <= b);
    const p = density ? density(x) : NaN;
    const pp = propDensity && !outside ? propDensity(x) : NaN;
    return {
      x,
      f: fx,
      p,
      ratio: fx === 0 ? 0 : p > 0 ? fx / p : NaN,
      uniformTerm: (b - a) * fx,
      propRatio: fx === 0 ? 0 : pp > 0 ? fx / pp : NaN,
      outside,
    };
  });
  const outside = rows.filter((r) => r.outside).map((r) => fmt(r.x));
  if (outside.length) {
    problems.push(
      fail(
        'outside',
        `Sample${outside.length > 1 ? 's' : ''} ${outside.join(', ')} lie${outside.length > 1 ? '' : 's'} outside [${fmt(a)}, ${fmt(b)}]: p = 0 there, so f/p is undefined and the estimate leaves ${outside.length > 1 ? 'them' : 'it'} out.`,
      ),
    );
  }
  const fv = Float64Array.from(rows, (r) => (r.outside ? NaN : r.f));
  const uniform = uniformEstimate(fv, a, b);
  let chosen: McEstimate | null = null;
  if (density) {
    const pv = Float64Array.from(rows, (r) => r.p);
    chosen = importanceEstimate(fv, pv);
    const zero = rows.filter((r) => !r.outside && r.p === 0 && r.f !== 0).map((r) => fmt(r.x));
    if (zero.length)
      problems.push(
        fail(
          'zero-pdf',
          `p = 0 at x = ${zero.join(', ')} where f ≠ 0: such a sample could never be drawn from p.`,
        ),
      );
  }
  let proportional: McEstimate | null = null;
  if (propDensity) {
    proportional = importanceEstimate(
      fv,
      Float64Array.from(rows, (r) => propDensity(r.x)),
    );
  }
  return { rows, chosen, uniform, proportional, problems };
}

/** Round half away from zero to `d` decimals (how a student writes 9.9856 → 9.99). */
export function roundTo(x: number, d: number): number {
  const k = 10 ** d;
  return (Math.sign(x) * Math.round(Math.abs(x) * k)) / k;
}

/** One comparison of a printed figure with the computed one. */
export interface KeyNote {
  what: string;
  printed: number;
  computed: number;
  /** The computed value rounded the way the key prints (2 decimals). */
  rounded: number;
  agrees: boolean;
}

/**
 * Compare the key's printed Q4(b) figures with the live computation (only when the scene shows the
 * exam's own problem: f = (x + 2)², [0, 2], the exam's four samples in order). Returns [] otherwise.
 */
export function keyComparison(
  fSrc: string,
  a: number,
  b: number,
  xs: readonly number[],
  table: SampleTable,
): KeyNote[] {
  const exam =
    squareShift(fSrc) === 2 &&
    a === EXAM_A &&
    b === EXAM_B &&
    xs.length === EXAM_SAMPLES.length &&
    xs.every((x, i) => x === EXAM_SAMPLES[i]);
  if (!exam) return [];
  const notes: KeyNote[] = table.rows.map((r, i) => {
    const printed = KEY_PRINTED.f[i];
    const rounded = roundTo(r.f, 2);
    return { what: `f(${fmt(r.x)})`, printed, computed: r.f, rounded, agrees: rounded === printed };
  });
  const est = table.uniform.estimate;
  notes.push({
    what: '⟨I⟩ uniform',
    printed: KEY_PRINTED.estimate,
    computed: est,
    rounded: roundTo(est, 2),
    agrees: roundTo(est, 2) === KEY_PRINTED.estimate,
  });
  return notes;
}

/**
 * The pdf of the race's importance lane: the chosen pdf unless it is uniform, else p ∝ f (null when
 * neither is usable), with the label the race shows for it.
 */
export function importanceLane(
  choice: PdfChoice | null,
  proportional: PdfChoice | null,
): { pdf: Extract<PdfChoice, { ok: true }>; label: string; name: string } | null {
  const pdf = choice?.ok && choice.kind !== 'uniform' ? choice : proportional?.ok ? proportional : null;
  if (!pdf) return null;
  const label =
    pdf.kind === 'proportional' ? 'p ∝ f: ' + pdf.label.replace(/ \(closed form.*\)$/, '') : pdf.label;
  return { pdf, label, name: LANE_NAME[pdf.kind] };
}

/** The importance lane's pdf in a few words (the figures' descriptions). */
const LANE_NAME: Record<PdfKind, string> = {
  uniform: 'uniform',
  proportional: 'p ∝ f',
  linear: 'the linear ramp',
  custom: 'your pdf',
};

/** Whether the page shows the exam's own Q4: f = (x + 2)², [0, 2] and the exam's four samples in order. */
export function isExamConfig(shift: number | null, a: number, b: number, xs: readonly number[]): boolean {
  return (
    shift === 2 &&
    a === EXAM_A &&
    b === EXAM_B &&
    xs.length === EXAM_SAMPLES.length &&
    xs.every((x, i) => x === EXAM_SAMPLES[i])
  );
}

/** The problem of an estimate with drawn samples (what estimate1D and EstimateRun1D take). */
export function drawnProblem(f: Fn1, sampler: Pdf1D, sequence: Strategy, seed: number): Problem1D {
  return { f, pdf: sampler, sequence, seed };
}

/** Estimate with n drawn samples on the main thread (small n; larger n runs in the worker). */
export function drawnEstimate(
  f: Fn1,
  sampler: Pdf1D,
  sequence: Strategy,
  seed: number,
  n: number,
): McEstimate {
  return estimate1D(drawnProblem(f, sampler, sequence, seed), n);
}

/** Largest n estimated synchronously on the main thread. */
export const SYNC_MAX_N = 100_000;

/** Curves of f and of the pdf scaled to f's range, on a grid of m points over [a, b]. */
export function curves(
  f: Fn1,
  density: Fn1 | null,
  a: number,
  b: number,
  m = 400,
): { x: Float64Array; f: Float64Array; p: Float64Array; scale: number } {
  const x = new Float64Array(m);
  const fy = new Float64Array(m);
  const py = new Float64Array(m);
  let fmax = 0;
  let pmax = 0;
  for (let i = 0; i < m; i++) {
    const xi = a + ((b - a) * i) / (m - 1);
    x[i] = xi;
    const v = f(xi);
    fy[i] = Number.isFinite(v) ? v : NaN;
    if (Number.isFinite(v)) fmax = Math.max(fmax, Math.abs(v));
    const p = density ? density(xi) : NaN;
    py[i] = p;
    if (Number.isFinite(p)) pmax = Math.max(pmax, p);
  }
  // scale the pdf to the height of f, rounded to a readable factor
  const scale = pmax > 0 && fmax > 0 ? Number((fmax / pmax).toPrecision(3)) : 1;
  for (let i = 0; i < m; i++) py[i] = py[i] * scale;
  return { x, f: fy, p: py, scale };
}

/** The value at x of a function tabulated on an evenly spaced grid (linear interpolation, clamped to its ends). */
export function gridAt(xs: ArrayLike<number>, ys: ArrayLike<number>, x: number): number {
  const n = xs.length;
  if (n < 2) return n ? ys[0] : NaN;
  const x0 = xs[0];
  const x1 = xs[n - 1];
  const q = ((x - x0) / (x1 - x0 || 1)) * (n - 1);
  const k = Math.max(0, Math.min(n - 2, Math.floor(q)));
  const w = q - k;
  return ys[k] * (1 - w) + ys[k + 1] * w;
}

/** The strategies compared in the convergence plots: [pdf, sequence, label]. */
export function comparedStrategies(
  selPdf: PdfKind,
  selSeq: Strategy,
  pdfOk: boolean,
): { pdf: PdfKind; seq: Strategy; label: string }[] {
  // each pdf with independent samples, then the uniform pdf with each better-spread sequence
  const pdfs: PdfKind[] = ['uniform', 'linear', 'proportional'];
  const seqs: Strategy[] = ['stratified', 'sobol'];
  type Compared = { pdf: PdfKind; seq: Strategy };
  const base: Compared[] = [
    ...pdfs.map((pdf): Compared => ({ pdf, seq: 'independent' })),
    ...seqs.map((seq): Compared => ({ pdf: 'uniform', seq })),
  ];
  if (pdfOk && !base.some((s) => s.pdf === selPdf && s.seq === selSeq))
    base.push({ pdf: selPdf, seq: selSeq });
  return base.map((s) => ({ ...s, label: strategyLabel(s.pdf, s.seq) }));
}

const PDF_LABEL: Record<PdfKind, string> = {
  uniform: 'uniform',
  linear: 'linear',
  proportional: 'p ∝ f',
  custom: 'custom p',
};
const SEQ_LABEL: Record<Strategy, string> = {
  independent: 'independent',
  stratified: 'stratified',
  halton: 'Halton',
  sobol: 'Sobol',
};

/** "uniform · Sobol" etc. */
export function strategyLabel(pdf: PdfKind, seq: Strategy): string {
  return `${PDF_LABEL[pdf]} · ${SEQ_LABEL[seq]}`;
}

/** Histogram of values (now in the core, re-exported for the scene's callers). */
export { histogram } from '../../core/estimators';

// ---------------------------------------------------------------------------------------------
// The animation: uniform against importance sampling, one sample at a time, on the
// same random numbers. Position t of the shared timeline = the number of samples drawn so far.
// ---------------------------------------------------------------------------------------------

/** Samples in one animation (the timeline's max). */
export const RACE_MAX = RACE_SAMPLES;
/** Seconds from 0 to RACE_MAX at 1× (= 250 samples per second; ¼× 62.5/s, 4× 1000/s). */
export const RACE_DURATION = 32.768;
/** Stream of the seeded generator the animation draws its ξᵢ from (independent of other runs). */
export const RACE_STREAM = 0x4d43;

/** One lane of the race: every sample and the running statistics after each, over the whole track. */
export interface RaceLane {
  /** xᵢ, i = 0 … max − 1. */
  x: Float64Array;
  /** The term f(xᵢ)/p(xᵢ). */
  term: Float64Array;
  /** Running mean of the first k + 1 terms (the estimate after k + 1 samples). */
  mean: Float64Array;
  /** Running Σ (term − mean)² of the first k + 1 terms (Welford's M₂). */
  m2: Float64Array;
}

/** The whole precomputed race for (f, [a, b], importance pdf, seed): what every t reads from. */
export interface RaceTrack {
  max: number;
  exact: number;
  /** ξᵢ ∈ [0, 1): the shared random numbers. */
  xi: Float64Array;
  uniform: RaceLane;
  importance: RaceLane;
}

function lane(n: number): RaceLane {
  return {
    x: new Float64Array(n),
    term: new Float64Array(n),
    mean: new Float64Array(n),
    m2: new Float64Array(n),
  };
}

/** A lane's running mean and M₂ over its first n terms, by Welford's update (one loop, no call per term). */
function runningMoments(L: RaceLane, n: number): void {
  let mean = 0;
  let m2 = 0;
  for (let i = 0; i < n; i++) {
    const y = L.term[i];
    const d = y - mean;
    mean += d / (i + 1);
    m2 += d * (y - mean);
    L.mean[i] = mean;
    L.m2[i] = m2;
  }
}

/**
 * Precompute the race: ξᵢ is the i-th draw of the seeded generator (Rng(seed, RACE_STREAM)), so a
 * track of `max` samples is a prefix of any longer one. The uniform lane uses xᵢ = a + (b − a)ξᵢ
 * and term (b − a) f(xᵢ); the importance lane xᵢ = P⁻¹(ξᵢ) and term f(xᵢ)/p(xᵢ). Running means and
 * M₂ by Welford's update. O(max) once per parameter change; raceAt(track, t) is then O(points).
 *
 * It runs while the scene first renders, on code the JIT has not warmed up yet, where a function
 * call per sample costs many times the arithmetic: ξ comes from Rng.fill (no call per draw), each
 * lane's terms are written in one loop and its running mean and M₂ in one more. The arithmetic is the plain
 * per-sample one's (tests/scenes/monte-carlo/race.test.ts compares them exactly).
 */
export function raceTrack(
  f: Fn1,
  a: number,
  b: number,
  importance: Pdf1D,
  exact: number,
  seed: number,
  max = RACE_MAX,
): RaceTrack {
  const xi = new Rng(seed, RACE_STREAM).fill(new Float64Array(max));
  const U = lane(max);
  const I = lane(max);
  const w = b - a;
  for (let i = 0; i < max; i++) {
    const x = a + w * xi[i];
    const y = w * f(x);
    U.x[i] = x;
    U.term[i] = y;
  }
  // per sample, not the batched sampler: a pdf's batch may round differently in the last bit
  for (let i = 0; i < max; i++) {
    const x = importance.sample(xi[i]);
    I.x[i] = x;
    const fx = f(x);
    const y = fx === 0 ? 0 : fx / importance.pdf(x);
    I.term[i] = y;
  }
  runningMoments(U, max);
  runningMoments(I, max);
  return { max, exact, xi, uniform: U, importance: I };
}

/** The state of one lane after t samples. */
export interface LaneState {
  n: number;
  /** The newest sample (index t − 1) and its term; NaN before the first. */
  x: number;
  term: number;
  estimate: number;
  /** s/√N with s² the unbiased sample variance; NaN for N < 2. */
  stderr: number;
  absError: number;
  /** Whether the terms' spread s is zero to rounding (see {@link zeroToRounding}); false for N < 2. */
  zeroVariance: boolean;
}

/** Sample counts at which the growing curves are drawn: 1 … 32 each, then 48 per decade up to max. */
export function racePoints(max: number): number[] {
  const out: number[] = [];
  for (let n = 1; n <= Math.min(32, max); n++) out.push(n);
  const perDecade = 48;
  for (let k = Math.ceil(Math.log10(33) * perDecade); ; k++) {
    const n = Math.round(10 ** (k / perDecade));
    if (n > max) break;
    if (n > out[out.length - 1]) out.push(n);
  }
  return out;
}

/** One lane's state after t samples (exported for the per-frame drawing of the race). */
export function raceLaneAt(L: RaceLane, t: number, exact: number): LaneState {
  return laneAt(L, t, exact);
}

function laneAt(L: RaceLane, t: number, exact: number): LaneState {
  if (t < 1)
    return { n: 0, x: NaN, term: NaN, estimate: NaN, stderr: NaN, absError: NaN, zeroVariance: false };
  const k = t - 1;
  const est = L.mean[k];
  return {
    n: t,
    x: L.x[k],
    term: L.term[k],
    estimate: est,
    stderr: t > 1 ? Math.sqrt(L.m2[k] / (t - 1) / t) : NaN,
    absError: Math.abs(est - exact),
    zeroVariance: t > 1 && zeroToRounding(Math.sqrt(Math.max(0, L.m2[k]) / (t - 1)), est),
  };
}

/** What the animation shows at position t (a pure function of the track, i.e. of params and seed, and t). */
export interface RaceFrame {
  t: number;
  uniform: LaneState;
  importance: LaneState;
  /** Curves up to t: sample counts (racePoints ≤ t, and t itself) with each lane's estimate, ±SE and |error|. */
  curve: {
    n: number[];
    u: number[];
    uSe: number[];
    uErr: number[];
    i: number[];
    iSe: number[];
    iErr: number[];
  };
  /** The most recent samples (up to `recent`), oldest first, for the rug under the integrand. */
  recentU: number[];
  recentI: number[];
}

export function raceAt(
  track: RaceTrack,
  t: number,
  points: readonly number[] = racePoints(track.max),
  recent = 40,
): RaceFrame {
  t = Math.max(0, Math.min(track.max, Math.floor(t)));
  const curve: RaceFrame['curve'] = { n: [], u: [], uSe: [], uErr: [], i: [], iSe: [], iErr: [] };
  const push = (n: number) => {
    const u = laneAt(track.uniform, n, track.exact);
    const i = laneAt(track.importance, n, track.exact);
    curve.n.push(n);
    curve.u.push(u.estimate);
    curve.uSe.push(u.stderr);
    curve.uErr.push(u.absError);
    curve.i.push(i.estimate);
    curve.iSe.push(i.stderr);
    curve.iErr.push(i.absError);
  };
  for (const n of points) {
    if (n >= t) break;
    push(n);
  }
  if (t >= 1) push(t);
  return { ...raceHeadAt(track, t, recent), curve };
}

/** The part of {@link raceAt} that is not the growing curves: both lanes at t and the latest samples, O(recent). */
export function raceHeadAt(track: RaceTrack, t: number, recent = 40): Omit<RaceFrame, 'curve'> {
  t = Math.max(0, Math.min(track.max, Math.floor(t)));
  const from = Math.max(0, t - recent);
  return {
    t,
    uniform: laneAt(track.uniform, t, track.exact),
    importance: laneAt(track.importance, t, track.exact),
    recentU: Array.from(track.uniform.x.subarray(from, t)),
    recentI: Array.from(track.importance.x.subarray(from, t)),
  };
}

/**
 * Rounding allowance of {@link zeroToRounding}, in units of ε·|mean|. Each term f(x)/p(x) carries a
 * few roundings (the sample, f, p, the division), so terms that are equal in exact arithmetic differ
 * by a few ulps, and Welford's update adds a few more to s; any spread a real pdf leaves (a tabulated
 * p ∝ |f| leaves about 10⁻⁴ of the mean) is many orders of magnitude above this.
 */
export const ZERO_SPREAD_ULPS = 64;

/**
 * Whether a spread (the terms' standard deviation s) is zero to rounding: exactly 0, or at most
 * ZERO_SPREAD_ULPS · ε · |mean|, relative to the magnitude of the estimate and to machine epsilon
 * (so the verdict does not change when f is scaled by any power of two). Not finite: false.
 */
export function zeroToRounding(spread: number, mean: number): boolean {
  if (spread === 0) return true;
  return (
    Number.isFinite(spread) &&
    Number.isFinite(mean) &&
    spread <= ZERO_SPREAD_ULPS * Number.EPSILON * Math.abs(mean)
  );
}

/** Whether an estimate's terms have zero variance to rounding (s = √variance against the estimate). */
export function estimateHasZeroVariance(e: { n: number; variance: number; estimate: number }): boolean {
  return e.n > 1 && zeroToRounding(Math.sqrt(Math.max(0, e.variance)), e.estimate);
}

// ---------------------------------------------------------------------------------------------
// The race's histograms: every sample drawn so far, binned over [a, b], per lane
// ---------------------------------------------------------------------------------------------

/** Bins of the race's histograms over [a, b]. */
export const RACE_BINS = 24;

/**
 * The bin of each sample: ⌊(x − a)/(b − a) · bins⌋, the last bin closed at b (a sample outside
 * [a, b], which no sampler of the scene produces, goes to the nearest end bin). Once per track.
 */
export function raceBinIndex(xs: ArrayLike<number>, a: number, b: number, bins = RACE_BINS): Uint16Array {
  const out = new Uint16Array(xs.length);
  const k = bins / (b - a);
  for (let i = 0; i < xs.length; i++) {
    const j = Math.floor((xs[i] - a) * k);
    out[i] = j < 0 || !(j === j) ? 0 : j >= bins ? bins - 1 : j;
  }
  return out;
}

/** Counts per bin of the first t samples (the histogram of everything drawn so far), into `out`. */
export function raceCounts(
  index: Uint16Array,
  t: number,
  bins = RACE_BINS,
  out: Uint32Array = new Uint32Array(bins),
): Uint32Array {
  out.fill(0);
  const n = Math.max(0, Math.min(index.length, Math.floor(t)));
  for (let i = 0; i < n; i++) out[index[i]]++;
  return out;
}

/** Bin k's interval [lo, hi] over [a, b]. */
export function binRange(k: number, a: number, b: number, bins = RACE_BINS): [number, number] {
  const w = (b - a) / bins;
  return [a + k * w, k === bins - 1 ? b : a + (k + 1) * w];
}

/** How many of the first t samples lie in [lo, hi]. */
export function countIn(xs: ArrayLike<number>, t: number, lo: number, hi: number): number {
  let c = 0;
  const n = Math.max(0, Math.min(xs.length, Math.floor(t)));
  for (let i = 0; i < n; i++) if (xs[i] >= lo && xs[i] <= hi) c++;
  return c;
}

/**
 * The half of [a, b] where a pdf puts more than half of its mass (where importance samples crowd),
 * from its CDF at the midpoint; the right half when they are equal.
 */
export function heavierHalf(pdf: Pick<Pdf1D, 'invert'>, a: number, b: number): [number, number] {
  const m = (a + b) / 2;
  return pdf.invert(m) > 0.5 ? [a, m] : [m, b];
}

// ---------------------------------------------------------------------------------------------
// The exam's Q4 worked out (live numbers for the derivations)
// ---------------------------------------------------------------------------------------------

/**
 * Q4(a) for f = (x + c)² on [a, b]: expansion x² + 2c x + c², antiderivative
 * F(x) = x³/3 + c x² + c² x, and F(b) − F(a) term by term.
 */
export function squareAntiderivative(c: number, a: number, b: number) {
  const F = (x: number) => ({ cube: (x * x * x) / 3, lin2: c * x * x, lin: c * c * x });
  const Fb = F(b);
  const Fa = F(a);
  const total = (v: { cube: number; lin2: number; lin: number }) => v.cube + v.lin2 + v.lin;
  return {
    twoC: 2 * c,
    c2: c * c,
    Fb,
    Fa,
    valueB: total(Fb),
    valueA: total(Fa),
    value: total(Fb) - total(Fa),
  };
}

/** Q4(c): the normalization of p ∝ (x + c)² on [a, b]: p = 3(x + c)² / D with D = 3∫f = (b + c)³ − (a + c)³. */
export function squareNormalizer(c: number, a: number, b: number): number {
  return (b + c) ** 3 - (a + c) ** 3;
}

/** Values of a strategy's convergence-series error at rounding level at every N (zero variance). */
export function atRoundingLevel(values: ArrayLike<number>, reference: number): boolean {
  const tiny = Math.abs(reference) * 1e-15 || 1e-300;
  let any = false;
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    if (!Number.isFinite(v)) continue;
    any = true;
    if (v > tiny * 100) return false;
  }
  return any;
}

/** Order (x, y) points by x, so a curve against measured time never doubles back. */
export function sortedByX<T extends { x: number }>(pts: readonly T[]): T[] {
  return [...pts].sort((p, q) => p.x - q.x);
}

/** Stratified and low-discrepancy points are not independent: s/√N is no error estimate for them. */
export function stderrIsValid(seq: Strategy): boolean {
  return seq === 'independent';
}
