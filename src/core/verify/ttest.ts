/**
 * t-tests of Monte Carlo estimators, the way renderers test for bias (Nori's `ttest`: a Student
 * t-test of an estimate against its analytic value; Jung, Hanika and Dachsbacher, "Detecting Bias
 * in Monte Carlo Renderers using Welch's t-test", JCGT 9(2), 2020: two estimators against each
 * other). An unbiased estimator's sample mean is, for large N, normal around the true value, so
 *
 * - Student: t = (x̄ − μ₀) / (s/√N), ν = N − 1;
 * - Welch:   t = (x̄₁ − x̄₂) / √(s₁²/N₁ + s₂²/N₂),
 *            ν = (s₁²/N₁ + s₂²/N₂)² / ((s₁²/N₁)²/(N₁ − 1) + (s₂²/N₂)²/(N₂ − 1))  (Welch–Satterthwaite);
 *
 * the two-sided p-value is P[|T_ν| ≥ |t|]. The hypothesis "unbiased" is rejected when p < α, with α
 * Šidák-corrected when several tests run together (./sidak), so that the chance of any
 * false rejection over the whole batch is the stated α.
 */
import { sidakAlpha } from './sidak';
import { studentTTwoSided } from './studentT';

/** Sample statistics of one estimator: mean, unbiased sample variance s² of the terms, count N. */
export interface SampleStats {
  mean: number;
  variance: number;
  n: number;
}

/** Outcome of a t-test. */
export interface TTestResult {
  /** The t statistic (±∞ when the variance is zero and the means differ beyond rounding). */
  t: number;
  /** Degrees of freedom ν (NaN when undefined, e.g. zero variance). */
  dof: number;
  /** Two-sided p-value P[|T_ν| ≥ |t|]; NaN when the test cannot be run (N < 2, non-finite input). */
  pValue: number;
  /** Requested overall significance. */
  alpha: number;
  /** Per-test significance after the Šidák correction over `tests` tests. */
  sidakAlpha: number;
  /** True when the hypothesis of equal means stands: pValue ≥ sidakAlpha. */
  pass: boolean;
}

/**
 * Two means that differ by no more than this relative amount count as equal when the variance is
 * zero (a zero-variance estimator, e.g. importance sampling with p ∝ f, still rounds its terms).
 */
const ZERO_VARIANCE_TOLERANCE = 1e-12;

function result(t: number, dof: number, pValue: number, alpha: number, tests: number): TTestResult {
  const a = sidakAlpha(alpha, tests);
  return { t, dof, pValue, alpha, sidakAlpha: a, pass: pValue >= a };
}

/** t and p when the standard error is zero: equal means (up to rounding) pass, others fail. */
function degenerate(diff: number, scale: number, alpha: number, tests: number): TTestResult {
  const same = Math.abs(diff) <= ZERO_VARIANCE_TOLERANCE * scale;
  return result(same ? 0 : diff > 0 ? Infinity : -Infinity, NaN, same ? 1 : 0, alpha, tests);
}

function usable(s: SampleStats): boolean {
  return Number.isFinite(s.mean) && Number.isFinite(s.variance) && s.variance >= 0 && s.n >= 2;
}

/**
 * Student's one-sample t-test of an estimator's sample statistics against an exact value μ₀.
 * `alpha` is the overall significance (default 0.01), `tests` the number of tests in the batch.
 */
export function studentTTest(sample: SampleStats, exact: number, alpha = 0.01, tests = 1): TTestResult {
  if (!usable(sample) || !Number.isFinite(exact)) return result(NaN, NaN, NaN, alpha, tests);
  const diff = sample.mean - exact;
  const se = Math.sqrt(sample.variance / sample.n);
  if (se === 0) return degenerate(diff, Math.max(Math.abs(sample.mean), Math.abs(exact)), alpha, tests);
  const t = diff / se;
  const dof = sample.n - 1;
  return result(t, dof, studentTTwoSided(t, dof), alpha, tests);
}

/** The Welch t statistic, its degrees of freedom and its two-sided p (NaN p when undefined). */
export function welchStatistic(a: SampleStats, b: SampleStats): { t: number; dof: number; pValue: number } {
  if (!usable(a) || !usable(b)) return { t: NaN, dof: NaN, pValue: NaN };
  const va = a.variance / a.n;
  const vb = b.variance / b.n;
  const diff = a.mean - b.mean;
  const se2 = va + vb;
  if (se2 === 0) {
    const same = Math.abs(diff) <= ZERO_VARIANCE_TOLERANCE * Math.max(Math.abs(a.mean), Math.abs(b.mean));
    return { t: same ? 0 : diff > 0 ? Infinity : -Infinity, dof: NaN, pValue: same ? 1 : 0 };
  }
  const t = diff / Math.sqrt(se2);
  const dof = (se2 * se2) / ((va * va) / (a.n - 1) + (vb * vb) / (b.n - 1));
  return { t, dof, pValue: studentTTwoSided(t, dof) };
}

/** Welch's two-sample t-test: do two estimators have the same mean? */
export function welchTTest(a: SampleStats, b: SampleStats, alpha = 0.01, tests = 1): TTestResult {
  const w = welchStatistic(a, b);
  return result(w.t, w.dof, w.pValue, alpha, tests);
}
