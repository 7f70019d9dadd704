/**
 * The equal-time comparison with a clock that counts work (one tick per pass) instead of time, so
 * every number is deterministic: each strategy runs the same number of passes; its curve is its
 * image's relMSE after each pass, recomputed here from a fresh render; the ranking is the order of
 * the final relMSE; the equal-error target is reached by every strategy; and the better
 * strategies of the exam scene's direct light rank above uniform hemisphere sampling; FLIP is
 * measured on a log-spaced set of passes and falls as the samples grow.
 */
import { describe, expect, it } from 'vitest';
import { STRATEGIES } from '../../../src/core/render/directLight';
import { equalErrorTarget, rankByError, runForTime, timeToError } from '../../../src/core/render/equalTime';
import { makeCpuRenderer, renderImage } from '../../../src/core/render/cpuRenderer';
import { referenceImage } from '../../../src/core/render/referenceImage';
import { relMse } from '../../../src/core/image/relMse';
import { displayFlipMean } from '../../../src/core/render/displayFlip';
import { defaultView, examScene } from '../../../src/core/render/scene';

const RES = 24;
const SCENE = examScene();
const VIEW = defaultView('exam');
const REF = referenceImage(SCENE, VIEW, RES, RES, 1).values;

/** A clock that advances by 1 "ms" each time it is read after the start. */
function ticks(): () => number {
  let t = 0;
  return () => t++;
}

describe('equal time', () => {
  const runs = STRATEGIES.map((strategy) =>
    runForTime(SCENE, VIEW, RES, { strategy, bounces: 1 }, 3, REF, 8, ticks()),
  );

  it('gives every strategy the same budget, and records relMSE after each pass', () => {
    for (const r of runs) {
      expect(r.spp).toBe(8);
      expect(r.curve.ms).toEqual([1, 2, 3, 4, 5, 6, 7, 8]);
      expect(r.relMse).toBe(r.curve.relMse[7]);
      // the same image rendered directly, measured independently
      const direct = renderImage(
        makeCpuRenderer(SCENE, VIEW, RES, RES, { strategy: r.strategy, bounces: 1 }, 3),
        RES,
        RES,
        8,
        1,
      );
      expect(Array.from(r.image)).toEqual(Array.from(direct));
      expect(r.relMse).toBeCloseTo(relMse(direct, REF), 14);
    }
  });

  it('ranks by the final relMSE; every strategy reaches the equal-error target', () => {
    const order = rankByError(runs);
    const errs = order.map((k) => runs[k].relMse);
    expect([...errs].sort((a, b) => a - b)).toEqual(errs);
    const target = equalErrorTarget(runs);
    expect(target).toBe(Math.max(...runs.map((r) => r.relMse)));
    for (const r of runs) expect(timeToError(r, target)).not.toBeNull();
    // uniform hemisphere sampling is the worst estimator of a small light's direct light
    expect(runs[order[order.length - 1]].strategy).toBe('uniform');
    expect(timeToError(runs[0], -1)).toBeNull();
  });

  it('runs at least one pass, however small the budget', () => {
    const r = runForTime(
      SCENE,
      VIEW,
      8,
      { strategy: 'area', bounces: 1 },
      1,
      referenceImage(SCENE, VIEW, 8, 8, 1).values,
      0,
      ticks(),
    );
    expect(r.spp).toBe(1);
    expect(r.curve.relMse).toHaveLength(1);
    expect(r.curve.flip).toHaveLength(1);
    expect(r.flip).toBe(r.curve.flip[0]);
  });

  it('measures FLIP after passes 1, 2, 4, 8 and the last, and only the passes are timed', () => {
    const r = runForTime(SCENE, VIEW, RES, { strategy: 'cosine', bounces: 1 }, 3, REF, 6, ticks());
    // six passes: measured after 1, 2, 4 and the sixth, not after 3 and 5
    expect(r.curve.flip.map((f) => !Number.isNaN(f))).toEqual([true, true, false, true, false, true]);
    expect(r.flip).toBe(r.curve.flip[5]);
    expect(r.flip).toBe(displayFlipMean(r.image, REF, RES));
    // the measuring takes clock reads of its own in no pass: one tick per pass, as without it
    expect(r.curve.ms).toEqual([1, 2, 3, 4, 5, 6]);
    // more samples, a smaller perceived error where the image is noisy (a strategy that is already
    // nearly exact at one sample shows its error mostly in the 8-bit levels, not in its noise)
    for (const run of runs)
      if (run.curve.relMse[0] > 0.05) expect(run.curve.flip[7], run.strategy).toBeLessThan(run.curve.flip[0]);
  });
});
