/**
 * The race: uniform against importance sampling, one sample at a time, on the same random
 * numbers. Position t of the shared timeline = the number of samples drawn so far.
 */
import type { Pdf1D } from '../../core/sampling/pdf1d';
import { Rng } from '../../core/random/rng';
import type { Fn1 } from './integral';
import { RACE_SAMPLES } from './params';
import { zeroToRounding } from './zeroVariance';

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
