/**
 * The Q2 estimators of ∫ f dω on one point set: uniform (2π/N) Σ f and importance (1/N) Σ f/p;
 * repeated over many seeds (the histogram of estimates) and the RMSE over randomized runs.
 */
import { TWO_PI, sampleUniformHemisphereBatch, sphericalPhi, sphericalTheta } from '../../core/sampling';
import { fillSequence2D, runSeed, type SequenceKind } from '../../core/random';
import { estimateFromTerms, type McEstimate } from '../../core/estimators';
import type { Lobe } from './lobe';
import type { Integrand } from './integral';

/** The two Q2 estimators on the same point set: uniform (2π/N) Σ f and importance (1/N) Σ f/p. */
export interface Q2Estimates {
  uniform: McEstimate;
  importance: McEstimate;
  /** Samples (of both point sets) where f itself is NaN or ±∞: the estimators have no value then. */
  fNonFinite: number;
  /** Importance samples where p = 0 (or is not finite) although f ≠ 0. */
  pZero: number;
}

/**
 * Q2 estimates from n points u (ξ pairs): the uniform estimator warps them with the uniform
 * hemisphere map, the importance estimator with the lobe (its directions `dirs`).
 * Terms: Yᵢ = 2π f(Xᵢ) and Yᵢ = f(Xᵢ)/p(Xᵢ) (0 when f = 0; invalid when p = 0 and f ≠ 0).
 */
export function q2Estimates(
  lobe: Lobe | null,
  f: Integrand,
  u: Float64Array,
  dirs: Float64Array | null,
  n: number,
  scratch?: { uni: Float64Array; terms: Float64Array },
): Q2Estimates {
  const uni = scratch?.uni ?? new Float64Array(3 * n);
  const terms = scratch?.terms ?? new Float64Array(n);
  sampleUniformHemisphereBatch(u, uni, n);
  let fNonFinite = 0;
  let pZero = 0;
  for (let i = 0; i < n; i++) {
    const x = uni[3 * i];
    const y = uni[3 * i + 1];
    const z = uni[3 * i + 2];
    const fv = f(sphericalTheta(x, y, z), sphericalPhi(x, y));
    if (!Number.isFinite(fv)) fNonFinite++;
    terms[i] = TWO_PI * fv;
  }
  const uniform = estimateFromTerms(terms, 0, n);
  let importance: McEstimate = { n: 0, estimate: NaN, variance: NaN, stderr: NaN, invalid: 0 };
  if (lobe && dirs) {
    for (let i = 0; i < n; i++) {
      const x = dirs[3 * i];
      const y = dirs[3 * i + 1];
      const z = dirs[3 * i + 2];
      const fv = f(sphericalTheta(x, y, z), sphericalPhi(x, y));
      const p = lobe.pdf(x, y, z);
      if (!Number.isFinite(fv)) fNonFinite++;
      else if (fv !== 0 && !(p > 0 && Number.isFinite(p))) pZero++;
      terms[i] = fv === 0 ? 0 : p > 0 && Number.isFinite(p) && Number.isFinite(fv) ? fv / p : NaN;
    }
    importance = estimateFromTerms(terms, 0, n);
  }
  return { uniform, importance, fNonFinite, pZero };
}

/**
 * "Repeat many times": `runs` independent estimates with `perRun` samples each (point set of
 * kind `kind`, seeds derived from `seed`), for the histogram of estimates (Q2(c): unbiasedness).
 */
export function repeatEstimates(
  lobe: Lobe | null,
  f: Integrand,
  kind: SequenceKind,
  seed: number,
  runs: number,
  perRun: number,
  onProgress?: (fraction: number) => void,
): { uniform: Float64Array; importance: Float64Array } {
  const uniform = new Float64Array(runs);
  const importance = new Float64Array(runs);
  const u = new Float64Array(2 * perRun);
  const dirs = new Float64Array(3 * perRun);
  const scratch = { uni: new Float64Array(3 * perRun), terms: new Float64Array(perRun) };
  for (let r = 0; r < runs; r++) {
    fillSequence2D(kind, runSeed(seed, r), perRun, u);
    if (lobe) lobe.sampleBatch(u, dirs, perRun);
    const e = q2Estimates(lobe, f, u, lobe ? dirs : null, perRun, scratch);
    uniform[r] = e.uniform.estimate;
    importance[r] = e.importance.estimate;
    if (onProgress && (r & 63) === 63) onProgress((r + 1) / runs);
  }
  return { uniform, importance };
}

// ---- error of stratified / quasi-random estimates: RMSE over randomized runs ---------------------

/** RMSE of both estimators over `runs` independently randomized point sets of n points each. */
export interface RmseResult {
  runs: number;
  uniform: number;
  importance: number;
}

/**
 * s/√N assumes independent samples; for stratified, Halton and Sobol points it is not an error
 * estimate. The error is measured instead: `runs` independent randomizations (jitter, Owen
 * scrambling, seeds derived from `seed`), RMSE = √(mean (⟨I⟩ᵣ − I)²) against the quadrature value.
 */
export function rmseOverRuns(
  lobe: Lobe | null,
  f: Integrand,
  kind: SequenceKind,
  seed: number,
  n: number,
  exact: number,
  runs = 16,
): RmseResult {
  const r = repeatEstimates(lobe, f, kind, seed, runs, n);
  const rmse = (a: Float64Array) => {
    let s = 0;
    for (const x of a) s += (x - exact) ** 2;
    return Math.sqrt(s / a.length);
  };
  return { runs, uniform: rmse(r.uniform), importance: lobe ? rmse(r.importance) : NaN };
}
