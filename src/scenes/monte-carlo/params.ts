/**
 * URL parameters of the Monte Carlo scene (contract: `..docs/urls.md`, route
 * `#/monte-carlo`): f, a, b, pdf, pdfexpr, strategy, samples, n, seed.
 * Added by this scene (the contract only grows): `hn` (samples per estimate in the unbiasedness
 * histogram), `runs` (independent runs behind the RMSE curves), and the animation's `t` (samples
 * drawn so far) and `play`.
 */
import type { ParamSchema } from '../../kit/params';
import { timelineParams } from '../../kit/timeline';

/** Samples in the animation (the timeline's t is the sample index 0…RACE_MAX). Mirrors model.RACE_MAX. */
export const RACE_SAMPLES = 8192;
/**
 * Where the animation opens: enough samples that the histograms show where each strategy's samples
 * crowd and the estimates have settled, with most of the run still to play.
 */
export const RACE_OPEN = 1024;

export const PDF_KINDS = ['uniform', 'proportional', 'linear', 'custom'] as const;
export type PdfKind = (typeof PDF_KINDS)[number];
export const STRATEGIES = ['independent', 'stratified', 'halton', 'sobol'] as const;
export type Strategy = (typeof STRATEGIES)[number];

/** Largest sample count a run may ask for (worker, with progress and cancel). */
export const MAX_N = 10_000_000;

export const schema = {
  f: { kind: 'string', default: '(x+2)^2', maxLength: 400, label: 'integrand f(x)', expression: ['x'] },
  a: { kind: 'number', default: 0, min: -1000, max: 1000, label: 'lower limit a' },
  b: { kind: 'number', default: 2, min: -1000, max: 1000, label: 'upper limit b' },
  pdf: {
    kind: 'enum',
    default: 'uniform',
    values: PDF_KINDS,
    aliases: {
      importance: 'proportional',
      proportional_to_f: 'proportional',
      f: 'proportional',
      typed: 'custom',
      ramp: 'linear',
    },
  },
  pdfexpr: { kind: 'string', default: '1 + x', maxLength: 400, label: 'custom pdf p(x)', expression: ['x'] },
  strategy: {
    kind: 'enum',
    default: 'independent',
    values: STRATEGIES,
    aliases: { random: 'independent', iid: 'independent', jittered: 'stratified', qmc: 'sobol' },
  },
  samples: { kind: 'list', default: null, maxItems: 32, min: -1e6, max: 1e6, label: 'given samples x' },
  n: { kind: 'number', default: 10000, min: 1, max: MAX_N, integer: true, label: 'samples N' },
  seed: { kind: 'number', default: 1, min: 0, max: 4294967295, integer: true },
  hn: {
    kind: 'number',
    default: 16,
    min: 1,
    max: 10000,
    integer: true,
    label: 'samples per estimate (histogram)',
  },
  runs: { kind: 'number', default: 32, min: 4, max: 256, integer: true, label: 'independent runs (RMSE)' },
  // the animation: t = samples drawn so far (0…RACE_SAMPLES, opening at RACE_OPEN), play = 1 while playing
  ...timelineParams({ max: RACE_SAMPLES, integer: true, default: RACE_OPEN }),
} as const satisfies ParamSchema;

export type McSchema = typeof schema;
