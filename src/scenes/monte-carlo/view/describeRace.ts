/**
 * The race's figures in words: what a sighted student reads from them, with the live numbers. Pure
 * functions of the model's state at a position t (unit-tested); the figures use them as their
 * accessible descriptions.
 */
import { formatCount, formatSignificant } from '../../../ui/format';
import { summarizeSeries } from '../../../ui/summary';
import { binRange } from '../raceHistogram';
import type { LaneState } from '../race';

const num = (x: number, digits: number) => (Number.isFinite(x) ? formatSignificant(x, digits, 'times') : '—');
const interval = (lo: number, hi: number) => `[${num(lo, 4)}, ${num(hi, 4)}]`;
const percent = (part: number, whole: number) => `${whole > 0 ? Math.round((100 * part) / whole) : 0} %`;

/**
 * An estimate with its standard error as a student writes it: the error to one significant digit
 * (two when it starts with a 1), the estimate to the same decimal place: "18.6 ± 0.3".
 * A zero spread reads "18.67 ± 0"; without a standard error, the estimate alone.
 */
export function plusMinus(estimate: number, stderr: number, zero = false): string {
  if (!Number.isFinite(estimate)) return '—';
  if (zero) return `${num(estimate, 4)} ± 0`;
  if (!(Number.isFinite(stderr) && stderr > 0)) return num(estimate, 4);
  const e = Math.floor(Math.log10(stderr));
  const place = stderr / 10 ** e < 2 ? e - 1 : e; // exponent of the last digit written
  const unit = 10 ** place;
  const est = Math.round(estimate / unit) * unit;
  const se = Math.round(stderr / unit) * unit;
  if (place <= 0 && place >= -6) return `${est.toFixed(-place)} ± ${se.toFixed(-place)}`;
  if (place > 0 && Math.abs(est) < 1e6) return `${Math.round(est)} ± ${Math.round(se)}`;
  const digits = (v: number) => Math.max(1, Math.floor(Math.log10(Math.abs(v) || 1)) - place + 1);
  return `${num(est, digits(est))} ± ${num(se, digits(se))}`;
}

/** One lane's estimate as the description says it ("18.6 ± 0.3", "18.67 ± 0 (zero variance)"). */
export function laneText(s: LaneState): string {
  if (s.n < 1) return 'none yet';
  if (s.n < 2) return `${num(s.estimate, 4)} (one sample, no spread yet)`;
  return s.zeroVariance
    ? `${plusMinus(s.estimate, s.stderr, true)} (zero variance)`
    : plusMinus(s.estimate, s.stderr);
}

/** What the race shows at one position. */
export interface RaceScene {
  /** Samples drawn so far, and the most the race draws. */
  t: number;
  max: number;
  uniform: LaneState;
  importance: LaneState;
  /** The importance lane's pdf, short ("p ∝ f", "the linear ramp"). */
  importanceName: string;
  exact: number;
  /** The half of [a, b] where the importance pdf is heavier, and how many of each lane's t samples lie in it. */
  half: { lo: number; hi: number; uniform: number; importance: number } | null;
  /** ask=1: held at its start until the results are revealed (the exact value is not said). */
  held?: boolean;
}

/**
 * The race in one paragraph: "1024 samples: uniform estimate 18.6 ± 0.3, importance (p ∝ f) 18.67 ± 0
 * (zero variance); exact I = 18.67. …", then the errors and where the samples fell.
 */
export function describeRace(r: RaceScene): string {
  const exact = `exact I = ${num(r.exact, 6)}`;
  if (r.held)
    return `No samples drawn yet (0 of ${formatCount(r.max)}): they arrive once the results are revealed. Shown: f, and each lane's pdf over its empty histogram.`;
  if (r.t < 1)
    return `No samples drawn yet (0 of ${formatCount(r.max)}): play or step to draw them; ${exact}.`;
  const head =
    `${formatCount(r.t)} ${r.t === 1 ? 'sample' : 'samples'}: uniform estimate ${laneText(r.uniform)}, ` +
    `importance (${r.importanceName}) ${laneText(r.importance)}; ${exact}.`;
  const errors = ` |error|: uniform ${num(r.uniform.absError, 2)}, importance ${num(r.importance.absError, 2)}.`;
  const h = r.half;
  const where = h
    ? ` Where they fell: ${percent(h.importance, r.t)} of the importance samples lie in ` +
      `${interval(h.lo, h.hi)}, the half where its pdf is larger, against ${percent(h.uniform, r.t)} ` +
      `of the uniform ones.`
    : '';
  return head + errors + where;
}

/**
 * One lane's histogram in words: "Histogram of all 1024 uniform samples in 24 bins over [0, 2], against
 * p(x) = 1/2: fewest 30 in [0.583, 0.667], most 58 in [1.917, 2]; 51 % in [1, 2]."
 */
export function describeHistogram(o: {
  lane: string;
  pdf: string;
  counts: ArrayLike<number>;
  t: number;
  a: number;
  b: number;
  half: [number, number] | null;
  inHalf: number;
}): string {
  const bins = o.counts.length;
  const what = `Histogram of all ${formatCount(o.t)} ${o.lane} samples in ${bins} bins over ${interval(o.a, o.b)}, against ${o.pdf}`;
  if (o.t < 1 || bins < 1) return `${what}: no samples yet.`;
  let lo = 0;
  let hi = 0;
  for (let k = 1; k < bins; k++) {
    if (o.counts[k] < o.counts[lo]) lo = k;
    if (o.counts[k] > o.counts[hi]) hi = k;
  }
  const bin = (k: number) => interval(...binRange(k, o.a, o.b, bins));
  const half = o.half ? `; ${percent(o.inHalf, o.t)} in ${interval(o.half[0], o.half[1])}` : '';
  return `${what}: fewest ${formatCount(o.counts[lo])} in ${bin(lo)}, most ${formatCount(o.counts[hi])} in ${bin(hi)}${half}.`;
}

/** The race's curves up to t (model.raceAt's `curve`): N and each lane's estimate, ± s/√N, |error|. */
export interface RaceCurve {
  n: readonly number[];
  u: readonly number[];
  uSe: readonly number[];
  uErr: readonly number[];
  i: readonly number[];
  iSe: readonly number[];
  iErr: readonly number[];
}

/** The integrand plot: f over [a, b], the importance pdf on it, and the newest sample of each lane. */
export function describeIntegrand(o: {
  a: number;
  b: number;
  fMin: number;
  fMax: number;
  importanceName: string;
  uniform: LaneState;
  importance: LaneState;
}): string {
  const head = `f over ${interval(o.a, o.b)}, from ${num(o.fMin, 4)} to ${num(o.fMax, 4)}, with the importance pdf (${o.importanceName}) drawn scaled onto it.`;
  if (o.uniform.n < 1) return `${head} No sample has dropped yet.`;
  const k = o.uniform.n;
  return `${head} Sample ${formatCount(k)} dropped at x = ${num(o.uniform.x, 4)} (uniform) and x = ${num(o.importance.x, 4)} (importance); the ticks under f are the newest samples of each.`;
}

/** |error| against N on log–log axes, both lanes: the fitted slope of each, or "zero variance". */
export function describeErrors(c: RaceCurve, zeroVarianceImportance: boolean): string {
  if (c.n.length === 0) return '|error| against N, log–log: no samples yet.';
  const opts = { xLabel: 'N', yLabel: '|error|', logLog: true } as const;
  const u = `Uniform: ${summarizeSeries(c.n, c.uErr, opts)}`;
  const i = zeroVarianceImportance
    ? `Importance: zero variance, its |error| stays at rounding level (at most ${num(Math.max(...c.iErr.filter(Number.isFinite), 0), 2)}) at every N.`
    : `Importance: ${summarizeSeries(c.n, c.iErr, opts)}`;
  return `${u} ${i}`;
}

/** One lane's running estimate against N: its summary and where it ends against the exact I. */
export function describeEstimate(
  lane: string,
  n: readonly number[],
  est: readonly number[],
  s: LaneState,
  exact: number,
): string {
  if (n.length === 0) return `The ${lane} estimate against N: no samples yet.`;
  const sum = summarizeSeries(n, est, { xLabel: 'N', yLabel: `the ${lane} estimate` });
  return `${sum} Now ${laneText(s)} against the exact I = ${num(exact, 6)}.`;
}

/** Where a running estimate crosses the exact value (a sign change of estimate − I between points). */
export function crossings(xs: readonly number[], est: readonly number[], exact: number): number[] {
  const out: number[] = [];
  for (let k = 1; k < est.length; k++) {
    const d0 = est[k - 1] - exact;
    const d1 = est[k] - exact;
    if (Number.isFinite(d0) && Number.isFinite(d1) && d0 !== 0 && Math.sign(d0) !== Math.sign(d1))
      out.push(d1 === 0 ? xs[k] : xs[k - 1] + ((xs[k] - xs[k - 1]) * d0) / (d0 - d1));
  }
  return out;
}
