/**
 * The plain-data arguments of the render worker's `inspect` and `reference` tasks, built from the
 * page's model on the main thread (so the page and a test compute the same call).
 */
import type { InspectOptions } from '../../core/render/inspector';
import { STRATEGIES, type Strategy } from '../../core/render/directLight';
import type { TraceOptions } from '../../core/render/pathTrace';
import type { RenderSpec, View } from '../../core/render/scene';
import type { RenderModel } from './model';

export interface ReferenceArgs {
  spec: RenderSpec;
  view: View;
  res: number;
  trace: TraceOptions;
}

export interface InspectArgs extends ReferenceArgs {
  px: readonly [number, number];
  seed: number;
  pn: number;
}

/** The equal-time comparison: each strategy for `budgetMs` on a `res` × `res` image. */
export interface EqualTimeArgs extends ReferenceArgs {
  strategies: readonly Strategy[];
  budgetMs: number;
  seed: number;
}

/** The image side of the equal-time comparison (small: seven strategies share a few seconds). */
export const EQUAL_TIME_RES = 64;

export function equalTimeArgs(m: RenderModel, budgetMs: number): EqualTimeArgs {
  return {
    spec: m.spec,
    view: m.view,
    res: EQUAL_TIME_RES,
    trace: m.trace,
    strategies: STRATEGIES,
    budgetMs,
    seed: m.seed,
  };
}

/** The error from independent runs: `runs` renders of `spp` samples per pixel at `res`. */
export interface SpreadArgs extends ReferenceArgs {
  runs: number;
  spp: number;
  seed: number;
}

export const SPREAD_RUNS = 8;
export const SPREAD_SPP = 16;

export function spreadArgs(m: RenderModel): SpreadArgs {
  return {
    spec: m.spec,
    view: m.view,
    res: EQUAL_TIME_RES,
    trace: m.trace,
    runs: SPREAD_RUNS,
    spp: SPREAD_SPP,
    seed: m.seed,
  };
}

/**
 * Two strategies compared pixel by pixel: the model's estimator (its strategy and bias) and
 * `other`, unbiased, each rendered `runs` times as for the spread.
 */
export interface WelchArgs extends SpreadArgs {
  other: Strategy;
}

export function welchArgs(m: RenderModel, other: Strategy): WelchArgs {
  return { ...spreadArgs(m), other };
}

/** The CPU side of the comparison with the GPU renderer: `spp` samples per pixel with their squares. */
export interface MomentsArgs extends ReferenceArgs {
  spp: number;
  seed: number;
}

/** Samples per pixel each renderer takes in the comparison (small: the point is the test, not the image). */
export const COMPARE_SPP = 16;

export function momentsArgs(m: RenderModel): MomentsArgs {
  return { ...referenceArgs(m), spp: COMPARE_SPP, seed: m.seed };
}

export function referenceArgs(m: RenderModel): ReferenceArgs {
  return { spec: m.spec, view: m.view, res: m.res, trace: m.trace };
}

/** The inspector's call for the model's pixel, or null when no pixel is inspected. */
export function inspectArgs(m: RenderModel): InspectArgs | null {
  return m.px ? { ...referenceArgs(m), px: m.px, seed: m.seed, pn: m.pn } : null;
}

/** The options inspectPixel receives for these arguments. */
export function inspectOptions(a: InspectArgs): InspectOptions {
  return { ...a.trace, width: a.res, height: a.res, seed: a.seed, pn: a.pn };
}
