/**
 * Pearson's χ² goodness-of-fit test, as used to verify warps in Nori (`warptest`), Mitsuba
 * (`mitsuba.chi2.ChiSquareTest`) and pbrt-v4 (`sampling_test.cpp`): draw N samples, histogram
 * them, compare with the counts the pdf predicts, pool bins whose expected count is too small for
 * the χ² approximation, and reject at significance α (Šidák-corrected when several tests run).
 *
 * The same functions back the scenes' "run the χ² test" buttons and the unit tests.
 */
import gammainc from '@stdlib/math-base-special-gammainc';
import { sidakAlpha } from './sidak';

/**
 * Upper tail of the χ² distribution with `dof` degrees of freedom: P[X ≥ x] = Q(dof/2, x/2), the
 * regularized upper incomplete gamma function.
 *
 * Domain: x ∈ ℝ (x ≤ 0 gives 1, x = +∞ gives 0), dof > 0 (not necessarily an integer).
 * Returns NaN only for NaN x or dof ≤ 0 / non-finite dof.
 * Accuracy: Q is computed directly (continued fraction for the upper tail, not 1 − P), so it keeps
 * ~1e-13 relative accuracy far into the tail, e.g. Q(1, 500) = e^-500.
 * Source: @stdlib/math-base-special-gammainc (a port of Boost.Math `gamma_q`);
 * Numerical Recipes 3rd ed. §6.2 and §14.3.
 */
export function chi2UpperTail(x: number, dof: number): number {
  if (Number.isNaN(x) || !(dof > 0) || !Number.isFinite(dof)) return NaN;
  if (x <= 0) return 1;
  if (x === Infinity) return 0;
  // @stdlib signature: gammainc(x, a, regularized, upper)
  const q = gammainc(x / 2, dof / 2, true, true);
  return Math.min(1, Math.max(0, q));
}

/** Options of {@link chi2Test}. */
export interface Chi2Options {
  /** Bins with expected count below this are pooled into one bin (default 5). */
  minExpected?: number;
  /** Overall significance level (default 0.01). */
  alpha?: number;
  /** Number of tests run together, for the Šidák correction (default 1). */
  tests?: number;
}

/** Result of {@link chi2Test}. */
export interface Chi2Result {
  /** Pearson's statistic Σ (O − E)² / E over the (pooled) bins. */
  statistic: number;
  /** Degrees of freedom: number of bins used (after pooling) − 1. */
  dof: number;
  /**
   * P[χ²_dof ≥ statistic]; 0 when a sample fell where the pdf predicts none (or outside the
   * domain); NaN when the test cannot be run (fewer than two usable bins after pooling).
   */
  pValue: number;
  /** Requested overall significance. */
  alpha: number;
  /** Per-test significance after the Šidák correction. */
  sidakAlpha: number;
  /** True when the sample is consistent with the pdf: pValue ≥ sidakAlpha. */
  pass: boolean;
  /** How many original bins were merged into the pooled bin. */
  pooledBins: number;
  /** Number of original bins. */
  bins: number;
  /** Plain-language reason when the test failed for a reason other than a small p-value. */
  note?: string;
}

/**
 * Pearson χ² test of observed counts against expected counts, with pooling of low-expectation bins
 * (Mitsuba `ChiSquareTest.run`, after Nori's `warptest`): bins are visited in increasing order of
 * expected count; those with expected < `minExpected` are merged into one pooled bin (keep adding
 * to it while its expectation is still too small); a bin with expected 0 but observed > 0 fails
 * the test outright (pValue = 0) — the sampler produced an impossible sample.
 *
 * Domain: observed and expected of equal length, entries ≥ 0 and finite (counts, not
 * frequencies). The expected counts are NOT rescaled: if they do not sum to the number of samples
 * (a wrongly normalized pdf), the test is meant to notice. Measure: counts per bin.
 * Source: Pearson (1900); Mitsuba 3 `python/mitsuba/chi2.py`; Nori `src/warptest.cpp`.
 */
export function chi2Test(
  observed: ArrayLike<number>,
  expected: ArrayLike<number>,
  opts: Chi2Options = {},
): Chi2Result {
  const minExpected = opts.minExpected ?? 5;
  const alpha = opts.alpha ?? 0.01;
  const tests = opts.tests ?? 1;
  const sAlpha = sidakAlpha(alpha, tests);
  const bins = observed.length;
  const fail = (note: string, statistic = Infinity, dof = 0, pooledBins = 0): Chi2Result => ({
    statistic,
    dof,
    pValue: 0,
    alpha,
    sidakAlpha: sAlpha,
    pass: false,
    pooledBins,
    bins,
    note,
  });
  if (expected.length !== bins) return fail(`observed has ${bins} bins but expected has ${expected.length}`);
  for (let i = 0; i < bins; i++) {
    const o = observed[i];
    const e = expected[i];
    if (!Number.isFinite(o) || o < 0) return fail(`observed count in bin ${i} is ${o}`);
    if (!Number.isFinite(e) || e < 0)
      return fail(`expected count in bin ${i} is ${e} (the pdf is negative or not finite there)`);
  }
  const order = Array.from({ length: bins }, (_, i) => i).sort((a, b) => expected[a] - expected[b]);
  let statistic = 0;
  let dof = 0;
  let pooledObs = 0;
  let pooledExp = 0;
  let pooledBins = 0;
  for (const i of order) {
    const o = observed[i];
    const e = expected[i];
    if (e === 0) {
      if (o > 0) return fail(`${o} sample(s) fell in bin ${i}, where the pdf predicts none`);
      continue;
    }
    if (e < minExpected || (pooledExp > 0 && pooledExp < minExpected)) {
      pooledObs += o;
      pooledExp += e;
      pooledBins++;
    } else {
      const d = o - e;
      statistic += (d * d) / e;
      dof++;
    }
  }
  if (pooledExp > 0) {
    const d = pooledObs - pooledExp;
    statistic += (d * d) / pooledExp;
    dof++;
  }
  dof -= 1;
  if (dof < 1) {
    // Not a rejection: the test cannot be run. pValue is NaN ("does not apply"), pass is false.
    return {
      ...fail(
        'too few bins with enough expected samples for a χ² test (use more samples or fewer bins)',
        statistic,
        Math.max(dof, 0),
        pooledBins,
      ),
      pValue: NaN,
    };
  }
  const pValue = chi2UpperTail(statistic, dof);
  return { statistic, dof, pValue, alpha, sidakAlpha: sAlpha, pass: pValue >= sAlpha, pooledBins, bins };
}
