/**
 * The error from independent runs against the error against the reference: equal (to rounding)
 * for the furnace's zero-variance cosine sampling, close for an unbiased strategy, and far apart
 * for the biased variant (its bias² is error the runs' spread does not show).
 */
import { describe, expect, it } from 'vitest';
import { expectedError, independentRuns } from '../../../src/core/render/expectedError';
import { referenceImage } from '../../../src/core/render/referenceImage';
import { defaultView, examScene, furnaceScene } from '../../../src/core/render/scene';

const RES = 16;

describe('expected error from K independent runs', () => {
  it('is zero for cosine sampling in the furnace, where every sample is exact', () => {
    const scene = furnaceScene();
    const view = defaultView('furnace');
    const ref = referenceImage(scene, view, RES, RES, 1).values;
    const runs = independentRuns(scene, view, RES, { strategy: 'cosine', bounces: 1 }, 5, 4, 2);
    const e = expectedError(runs, ref);
    expect(e.pixels).toBeGreaterThan(0);
    expect(e.expectedMse).toBeLessThan(1e-24);
    expect(e.measuredMse).toBeLessThan(1e-24);
  });

  it('predicts the measured MSE of an unbiased strategy, and not of a biased one', () => {
    const scene = examScene();
    const view = defaultView('exam');
    const ref = referenceImage(scene, view, RES, RES, 1).values;
    const fair = expectedError(
      independentRuns(scene, view, RES, { strategy: 'area', bounces: 1 }, 9, 16, 4),
      ref,
    );
    expect(fair.pixels).toBeGreaterThan(50);
    expect(fair.measuredMse / fair.expectedMse).toBeGreaterThan(0.8);
    expect(fair.measuredMse / fair.expectedMse).toBeLessThan(1.25);
    const slip = expectedError(
      // more samples per pixel: the variance falls, the bias stays
      independentRuns(scene, view, RES, { strategy: 'area', bounces: 1, bias: 'no-cos-l' }, 9, 16, 64),
      ref,
    );
    expect(slip.measuredMse / slip.expectedMse).toBeGreaterThan(2);
  });
});
