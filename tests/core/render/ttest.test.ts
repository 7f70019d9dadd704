/**
 * The inspector's t-test: every correct strategy passes it at every tested pixel (the exact
 * reference, Student; the converged one, Welch), and the deliberately biased variants
 * (core/render/bias.ts) fail it wherever they change the estimator. Seeds are fixed; the test's
 * α (0.01) bounds how often a correct strategy could fail by chance at these seeds.
 */
import { describe, expect, it } from 'vitest';
import { inspectPixel } from '../../../src/core/render/inspector';
import { STRATEGIES, type Strategy } from '../../../src/core/render/directLight';
import { biasApplies, biasedTerm, CLAMP_MAX, type Bias } from '../../../src/core/render/bias';
import { defaultView, examScene } from '../../../src/core/render/scene';

const W = 48;
const VIEW = defaultView('exam');
const SCENE = examScene();
const FLOOR = [
  [6, 38],
  [45, 30],
];
const SPHERE = [22, 27];

const inspect = (i: number, j: number, strategy: Strategy, bias: Bias = 'none', bounces = 1) =>
  inspectPixel(SCENE, VIEW, i, j, { width: W, height: W, seed: 7, strategy, bounces, bias, pn: 4096 });

describe('the t-test of the pixel inspector', () => {
  it('passes every correct strategy against the exact reference (Student)', () => {
    for (const strategy of STRATEGIES)
      for (const [i, j] of [...FLOOR, SPHERE]) {
        const ins = inspect(i, j, strategy);
        expect(ins.referenceKind).toBe('exact');
        expect(ins.tTest?.pass, `${strategy} at (${i}, ${j}): p = ${ins.tTest?.pValue}`).toBe(true);
        expect(ins.tTest?.alpha).toBe(0.01);
      }
  });

  it('passes a correct strategy against a converged reference (Welch)', () => {
    const ins = inspect(6, 38, 'cosine', 'none', 3);
    expect(ins.referenceKind).toBe('converged');
    expect(ins.tTest?.pass).toBe(true);
    expect(Number.isFinite(ins.tTest?.dof)).toBe(true);
  });

  it('fails area sampling without cos θ_l, and clamped uniform sampling', () => {
    for (const [i, j] of FLOOR) {
      const slip = inspect(i, j, 'area', 'no-cos-l');
      expect(slip.estimate).toBeGreaterThan(slip.reference);
      expect(slip.tTest?.pass, `no-cos-l at (${i}, ${j}): p = ${slip.tTest?.pValue}`).toBe(false);
      const clamped = inspect(i, j, 'uniform', 'clamp');
      expect(clamped.estimate).toBeLessThan(clamped.reference);
      expect(clamped.tTest?.pass, `clamp at (${i}, ${j}): p = ${clamped.tTest?.pValue}`).toBe(false);
    }
  });

  it('says which variants change which strategies, and computes their terms', () => {
    expect(biasApplies('no-cos-l', 'area')).toBe(true);
    expect(biasApplies('no-cos-l', 'cosine')).toBe(false);
    expect(biasApplies('clamp', 'mis-power')).toBe(true);
    expect(biasApplies('none', 'area')).toBe(false);
    expect(biasedTerm('no-cos-l', 0.3, 'area', 0.5)).toBeCloseTo(0.6, 15);
    expect(biasedTerm('no-cos-l', 0.3, 'bsdf', 0.5)).toBe(0.3);
    expect(biasedTerm('clamp', 5, 'uniform', NaN)).toBe(CLAMP_MAX);
    expect(biasedTerm('none', 5, 'area', 0.5)).toBe(5);
    // a variant that does not apply leaves the estimator exactly as it was
    expect(inspect(6, 38, 'cosine', 'no-cos-l').estimate).toBe(inspect(6, 38, 'cosine').estimate);
  });
});
