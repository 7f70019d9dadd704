/**
 * One draw of n samples: the point set's (ξ₁, ξ₂), the lobe's directions, and every statistic the
 * scene shows about them (computed in the worker for big n).
 */
import { fillSequence2D, type SequenceKind } from '../../core/random';
import type { HemisphereChi2Result } from '../../core/verify';
import type { McEstimate } from '../../core/estimators';
import type { Lobe } from './lobe';
import { checkedIntegral, type Integrand } from './integral';
import { chi2OfDirections, marginalHistograms, type DensityHistogram } from './sampleCheck';
import { q2Estimates, rmseOverRuns, type Q2Estimates, type RmseResult } from './q2Estimates';
import { varianceCheck, type VarianceCheck } from './varianceCheck';

/** The n points (ξ₁, ξ₂) of the chosen set, interleaved, into `out` (length ≥ 2n). */
export function drawUniforms(
  kind: SequenceKind,
  seed: number,
  n: number,
  out = new Float64Array(2 * n),
): Float64Array {
  return fillSequence2D(kind, seed, n, out);
}

/** Directions of the lobe for the n points of the set: 3n numbers. */
export function drawDirections(
  lobe: Lobe,
  kind: SequenceKind,
  seed: number,
  n: number,
): { u: Float64Array; dirs: Float64Array } {
  const u = drawUniforms(kind, seed, n);
  const dirs = new Float64Array(3 * n);
  lobe.sampleBatch(u, dirs, n);
  return { u, dirs };
}

/** Everything the scene shows about one draw of n samples (computed in the worker for big n). */
export interface DrawStats {
  n: number;
  chi2: HemisphereChi2Result | null;
  hist: { theta: DensityHistogram; phi: DensityHistogram } | null;
  exact: number;
  /** Why ∫ f dω has no value (see {@link checkedIntegral}); null when it has one. */
  exactProblem: string | null;
  /** Set when the value is less accurate than its digits. */
  exactNote?: string;
  q2: Q2Estimates;
  /** Variances of one term of each estimator, by quadrature (null without a lobe, f or a finite ∫ f). */
  variance: VarianceCheck | null;
  /** For stratified / Halton / Sobol points: the RMSE over randomized runs (s/√N does not apply). */
  rmse: RmseResult | null;
}

/** Draw n samples of the lobe from the point set and compute all statistics the scene shows. */
export function computeDrawStats(
  lobe: Lobe | null,
  f: Integrand | null,
  kind: SequenceKind,
  seed: number,
  n: number,
): DrawStats {
  const u = drawUniforms(kind, seed, n);
  let dirs: Float64Array | null = null;
  if (lobe) {
    dirs = new Float64Array(3 * n);
    lobe.sampleBatch(u, dirs, n);
  }
  const nan: McEstimate = { n: 0, estimate: NaN, variance: NaN, stderr: NaN, invalid: 0 };
  const exact = f ? checkedIntegral(f) : null;
  const ev = exact ? exact.value : NaN;
  const haveExact = !!f && Number.isFinite(ev);
  return {
    n,
    chi2: lobe && dirs ? chi2OfDirections(lobe, dirs, n) : null,
    hist: lobe && dirs ? marginalHistograms(lobe, dirs, n) : null,
    exact: ev,
    exactProblem: exact ? exact.problem : null,
    ...(exact?.note ? { exactNote: exact.note } : {}),
    q2: f ? q2Estimates(lobe, f, u, dirs, n) : { uniform: nan, importance: nan, fNonFinite: 0, pZero: 0 },
    variance: lobe && f && haveExact ? varianceCheck(lobe, f, ev) : null,
    rmse: f && haveExact && kind !== 'independent' ? rmseOverRuns(lobe, f, kind, seed, n, ev) : null,
  };
}
