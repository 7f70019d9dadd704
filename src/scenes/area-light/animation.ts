/**
 * The animation of #/area-light: the samples of the chosen strategy arrive one by one; position t
 * on the shared timeline is the number of samples that have arrived. Everything shown at t is a
 * function of (params, seed, t) computed here.
 */
import { areaLightTerms, type LightStrategy } from '../../core/lights';
import { Rng } from '../../core/random';
import { Welford } from '../../core/estimators/welford';
import type { AreaLightModel } from './model';
import { STRATEGIES } from './strategies';

/**
 * Samples to draw: for each strategy, up to `count` samples (points on the light for the light
 * strategies, unit directions for cosine) and their estimator terms. Same streams as
 * {@link estimateAll}, so the drawn samples are the first ones of the estimate.
 */
export function drawSamples(
  m: AreaLightModel,
  strategy: LightStrategy,
  count: number,
  seed: number,
): { points: Float64Array; terms: Float64Array } {
  const u = new Float64Array(2 * count);
  new Rng(seed, STRATEGIES.indexOf(strategy)).fill(u);
  const points = new Float64Array(3 * count);
  const terms = new Float64Array(count);
  areaLightTerms(m.setup, strategy, u, count, terms, points);
  return { points, terms };
}

/** Most samples the animation shows (the timeline runs 0 … min(n, ANIM_MAX)). */
export const ANIM_MAX = 1024;

/** Length of the timeline for n samples. */
export function animationLength(n: number): number {
  return Math.max(1, Math.min(ANIM_MAX, Math.floor(n) || 1));
}

/** The samples of one strategy with the running estimate and standard error after each. */
export interface SampleRun {
  strategy: LightStrategy;
  count: number;
  points: Float64Array;
  terms: Float64Array;
  /** mean[i] = estimate after i + 1 samples. */
  mean: Float64Array;
  /** stderr[i] = s/√(i+1) after i + 1 samples (NaN for one sample). */
  stderr: Float64Array;
}

/** The first `count` samples of `strategy` (the estimate's own stream) and their running statistics (core Welford). */
export function sampleRun(
  m: AreaLightModel,
  strategy: LightStrategy,
  count: number,
  seed: number,
): SampleRun {
  const { points, terms } = drawSamples(m, strategy, count, seed);
  const mean = new Float64Array(count);
  const stderr = new Float64Array(count);
  const w = new Welford();
  for (let i = 0; i < count; i++) {
    w.add(terms[i]);
    mean[i] = w.mean;
    stderr[i] = w.standardError();
  }
  return { strategy, count, points, terms, mean, stderr };
}

/** What the animation shows at position t. */
export interface AnimationFrame {
  /** Samples arrived: floor(t) clamped to [0, count]. */
  k: number;
  /** Running estimate after k samples (NaN for k = 0). */
  estimate: number;
  /** Its standard error (NaN for k < 2). */
  stderr: number;
  /** Index of the newest sample (k − 1), or −1. */
  newest: number;
  /** The newest sample's term (NaN for k = 0). */
  newestTerm: number;
}

export function animationFrame(run: SampleRun, t: number): AnimationFrame {
  const k = Math.max(0, Math.min(run.count, Math.floor(Number.isFinite(t) ? t + 1e-9 : 0)));
  return {
    k,
    estimate: k > 0 ? run.mean[k - 1] : NaN,
    stderr: k > 1 ? run.stderr[k - 1] : NaN,
    newest: k - 1,
    newestTerm: k > 0 ? run.terms[k - 1] : NaN,
  };
}
