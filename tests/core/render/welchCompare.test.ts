/**
 * The render lab's comparison of two estimators pixel by pixel, at the size the page runs it: two
 * unbiased strategies that find the light with every sample agree (no pixel below the
 * Šidák-corrected level), and the same strategy with a deliberate bias (a missing cos θ_l) is
 * caught against an unbiased one. Also the per-pixel statistics of a stack of runs, against direct
 * sums.
 */
import { describe, expect, it } from 'vitest';
import { welchOfStrategies } from '../../../src/core/render/welchCompare';
import { pixelStatsOfRuns } from '../../../src/core/verify/welchMap';
import { defaultView, examScene } from '../../../src/core/render/scene';
import { TTEST_ALPHA } from '../../../src/core/render/inspector';
import type { Strategy } from '../../../src/core/render/directLight';
import type { Bias } from '../../../src/core/render/bias';

const SCENE = examScene();
const VIEW = defaultView('exam');
const RES = 32;
const run = (strategy: Strategy, bias: Bias, other: Strategy) =>
  welchOfStrategies(SCENE, VIEW, RES, { strategy, bounces: 1, bias }, other, 5, 8, 16, TTEST_ALPHA);

describe('welchOfStrategies', () => {
  it('passes two unbiased strategies', () => {
    for (const [a, b] of [
      ['area', 'solid-angle'],
      ['solid-angle', 'area'],
      ['mis-power', 'area'],
    ] as const) {
      const m = run(a, 'none', b);
      expect(m.tested).toBeGreaterThan(RES * RES * 0.5);
      expect(m.pass, `${a} against ${b}: ${m.rejected} pixels rejected, min p ${m.minP}`).toBe(true);
    }
  });

  it('fails a biased variant against an unbiased strategy', () => {
    const m = run('area', 'no-cos-l', 'solid-angle');
    expect(m.pass).toBe(false);
    expect(m.rejected).toBeGreaterThan(0);
  });
});

describe('pixelStatsOfRuns', () => {
  it('gives each pixel the mean, unbiased variance and count of its values over the runs', () => {
    const s = pixelStatsOfRuns([
      [1, 10],
      [3, 10],
      [5, 13],
    ]);
    expect(Array.from(s.mean)).toEqual([3, 11]);
    expect(Array.from(s.variance)).toEqual([4, 3]);
    expect(Array.from(s.count)).toEqual([3, 3]);
    expect(Number.isNaN(pixelStatsOfRuns([[2]]).variance[0])).toBe(true);
  });
});
