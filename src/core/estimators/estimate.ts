/**
 * One-dimensional Monte Carlo estimators over typed arrays (batched, no object per sample).
 *
 *   uniform:    ⟨I⟩ = (b − a)/N · Σ f(xᵢ),   xᵢ ~ U[a, b]            (exam Q4(b); Q2(a) with |D| = 2π)
 *   importance: ⟨I⟩ = 1/N · Σ f(xᵢ)/p(xᵢ),   xᵢ ~ p                   (exam Q2(b), Q4(c))
 *
 * Both are the sample mean of per-sample terms Yᵢ; their standard error is s/√N with s² the unbiased
 * sample variance of the Yᵢ (Welford). Source: pbrt-v4 §2.1.2–2.2 (the Monte Carlo estimator,
 * importance sampling); Veach's thesis §2.4.
 *
 * A term with p(xᵢ) = 0 and f(xᵢ) ≠ 0 cannot occur for a valid sampler (a sample is never drawn
 * where p = 0). If it does (e.g. a user pdf that is zero where f is not, or given samples outside
 * the support), the estimator is biased or infinite: such terms are counted in `invalid` and left
 * out of the mean, and callers must report them rather than show the number as an answer.
 */
import { Welford } from './welford';

/** Result of an estimator: the estimate, the per-term variance, its standard error. */
export interface McEstimate {
  /** Number of terms N that entered the mean. */
  n: number;
  /** The estimate ⟨I⟩ (NaN when N = 0). */
  estimate: number;
  /** Unbiased sample variance s² of the per-sample terms (0 when N < 2). */
  variance: number;
  /** Standard error s/√N of ⟨I⟩ (NaN when N < 2). */
  stderr: number;
  /** Terms left out because p(x) = 0 (or non-finite) while f(x) ≠ 0, or f(x) non-finite. */
  invalid: number;
}

/** The estimate a Welford accumulator holds (NaN with no valid term), with the count of invalid terms. */
export function finishEstimate(w: Welford, invalid: number): McEstimate {
  return {
    n: w.count,
    estimate: w.count > 0 ? w.mean : NaN,
    variance: w.variance(),
    stderr: w.standardError(),
    invalid,
  };
}

/**
 * Uniform estimator on [a, b]: terms Yᵢ = (b − a) f(xᵢ), estimate (b − a)/N Σ f(xᵢ).
 * Domain: fValues[start..end) = f(xᵢ) at xᵢ uniform on [a, b]; measure dx. Non-finite f values are
 * counted in `invalid` and skipped.
 */
export function uniformEstimate(
  fValues: ArrayLike<number>,
  a: number,
  b: number,
  start = 0,
  end = fValues.length,
): McEstimate {
  const w = new Welford();
  const len = b - a;
  let invalid = 0;
  for (let i = start; i < end; i++) {
    const f = fValues[i];
    if (!Number.isFinite(f)) {
      invalid++;
      continue;
    }
    w.add(len * f);
  }
  return finishEstimate(w, invalid);
}

/**
 * Importance-sampled terms Yᵢ = f(xᵢ)/p(xᵢ) written into the caller-owned `out` (batched kernel).
 * A term with f = 0 is 0 whatever p is (0/0 is defined as 0: such a sample contributes nothing).
 * A term with f ≠ 0 and p ≤ 0 or p non-finite, or f non-finite, is written as NaN and counted.
 * Domain: arrays of equal length ≥ end; measure: p is a density in the same measure as ∫ f dx.
 * @returns the number of invalid terms
 */
export function importanceTermsInto(
  fValues: ArrayLike<number>,
  pdfValues: ArrayLike<number>,
  out: Float64Array,
  start = 0,
  end = fValues.length,
): number {
  let invalid = 0;
  for (let i = start; i < end; i++) {
    const f = fValues[i];
    const p = pdfValues[i];
    if (f === 0) out[i] = 0;
    else if (p > 0 && p < Infinity && Number.isFinite(f)) out[i] = f / p;
    else {
      out[i] = NaN;
      invalid++;
    }
  }
  return invalid;
}

/**
 * Importance-sampled estimator ⟨I⟩ = 1/N Σ f(xᵢ)/p(xᵢ) over fValues/pdfValues[start..end).
 * Domain: xᵢ drawn from the density p (or given); measure dx. Invalid terms (see
 * {@link importanceTermsInto}) are counted and left out of the mean.
 */
export function importanceEstimate(
  fValues: ArrayLike<number>,
  pdfValues: ArrayLike<number>,
  start = 0,
  end = fValues.length,
): McEstimate {
  const w = new Welford();
  let invalid = 0;
  for (let i = start; i < end; i++) {
    const f = fValues[i];
    const p = pdfValues[i];
    if (f === 0) w.add(0);
    else if (p > 0 && p < Infinity && Number.isFinite(f)) w.add(f / p);
    else invalid++;
  }
  return finishEstimate(w, invalid);
}

/**
 * Estimate from precomputed per-sample terms Yᵢ (e.g. from {@link importanceTermsInto}); NaN
 * terms are counted as invalid and skipped.
 */
export function estimateFromTerms(terms: ArrayLike<number>, start = 0, end = terms.length): McEstimate {
  const w = new Welford();
  let invalid = 0;
  for (let i = start; i < end; i++) {
    const y = terms[i];
    if (Number.isFinite(y)) w.add(y);
    else invalid++;
  }
  return finishEstimate(w, invalid);
}
