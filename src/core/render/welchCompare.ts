/**
 * Two estimators of one image compared pixel by pixel (../verify/welchMap; Jung, Hanika and
 * Dachsbacher, JCGT 2020): `trace` (a strategy, perhaps with a deliberate bias) and the strategy
 * `other`, unbiased, each render the image `runs` times at `spp` samples per pixel from seeds of
 * their own (./expectedError independentRuns), and each pixel's two means are compared by Welch's
 * t-test at overall significance `alpha` (Šidák-corrected over the pixels).
 */
import { runSeed } from '../random/rng';
import { pixelStatsOfRuns, welchMap, type WelchMap } from '../verify/welchMap';
import type { Strategy } from './directLight';
import { independentRuns } from './expectedError';
import type { TraceOptions } from './pathTrace';
import type { RenderScene, View } from './scene';

export function welchOfStrategies(
  scene: RenderScene,
  view: View,
  res: number,
  trace: TraceOptions,
  other: Strategy,
  seed: number,
  runs: number,
  spp: number,
  alpha: number,
): WelchMap {
  const mine = independentRuns(scene, view, res, trace, seed, runs, spp);
  const theirs = independentRuns(
    scene,
    view,
    res,
    { ...trace, strategy: other, bias: 'none' },
    runSeed(seed, 1000),
    runs,
    spp,
  );
  return welchMap(pixelStatsOfRuns(mine), pixelStatsOfRuns(theirs), alpha);
}
