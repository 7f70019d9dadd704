/** Estimates with drawn samples (on the main thread for small n) and when s/√N is an error estimate. */
import { estimate1D, type McEstimate, type Problem1D } from '../../core/estimators';
import type { Pdf1D } from '../../core/sampling/pdf1d';
import type { Fn1 } from './integral';
import type { Strategy } from './params';

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

/** Stratified and low-discrepancy points are not independent: s/√N is no error estimate for them. */
export function stderrIsValid(seq: Strategy): boolean {
  return seq === 'independent';
}
