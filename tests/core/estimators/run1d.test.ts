import { describe, expect, it } from 'vitest';
import { ConvergenceRun1D, estimate1D, EstimateRun1D, BATCH } from '../../../src/core/estimators/run1d';
import { logSpacedCounts } from '../../../src/core/estimators/convergence';
import { RmseAccumulator } from '../../../src/core/estimators/rmse';
import { fitLogLogSlope } from '../../../src/core/estimators/slope';
import { squarePdf1D, uniformPdf1D } from '../../../src/core/sampling/pdf1d';
import { SEQUENCE_KINDS, type SequenceKind } from '../../../src/core/random/sequences';

const f = (x: number) => (x + 2) * (x + 2);
const I = 56 / 3;

describe('estimate1D', () => {
  it('p ∝ f gives 56/3 for every sequence (zero variance)', () => {
    for (const sequence of SEQUENCE_KINDS) {
      const r = estimate1D({ f, pdf: squarePdf1D(0, 2, 2), sequence, seed: 5 }, 10000);
      expect(r.estimate).toBeCloseTo(I, 12);
      expect(r.stderr).toBeLessThan(1e-12);
      expect(r.invalid).toBe(0);
    }
  });

  it('uniform sampling is within 4σ of 56/3 for every sequence', () => {
    for (const sequence of SEQUENCE_KINDS) {
      const r = estimate1D({ f, pdf: uniformPdf1D(0, 2), sequence, seed: 9 }, 20000);
      expect(Math.abs(r.estimate - I)).toBeLessThan(4 * r.stderr);
    }
  });

  it('counts terms where p = 0 but f ≠ 0 as invalid', () => {
    const pdf = uniformPdf1D(0, 2);
    const broken = {
      ...pdf,
      sampleBatch: (u: Float64Array, x: Float64Array, p: Float64Array, s: number, e: number) => {
        pdf.sampleBatch(u, x, p, s, e);
        p.fill(0, s, e);
      },
    };
    const r = estimate1D({ f, pdf: broken, sequence: 'independent', seed: 1 }, 100);
    expect(r.invalid).toBe(100);
    expect(Number.isNaN(r.estimate)).toBe(true);
  });
});

describe('EstimateRun1D', () => {
  it('one batch per step; the result equals estimate1D exactly, for every sequence and pdf', () => {
    const n = 2 * BATCH + 17;
    for (const sequence of SEQUENCE_KINDS) {
      for (const pdf of [uniformPdf1D(0, 2), squarePdf1D(0, 2, 2)]) {
        const prob = { f: (x: number) => Math.exp(x) * (x + 2), pdf, sequence, seed: 11 };
        const run = new EstimateRun1D(prob, n);
        let steps = 1;
        while (!run.step()) steps++;
        expect(steps).toBe(3);
        expect(run.step()).toBe(true); // nothing left: no change
        expect(run.result()).toEqual(estimate1D(prob, n));
      }
    }
  });

  it('partial results cover the points processed so far; p = 0 terms count as invalid', () => {
    const pdf = uniformPdf1D(0, 2);
    const run = new EstimateRun1D({ f, pdf, sequence: 'independent', seed: 3 }, BATCH + 5);
    expect(run.step()).toBe(false);
    expect(run.result().n).toBe(BATCH);
    const broken = {
      ...pdf,
      sampleBatch: (u: Float64Array, x: Float64Array, p: Float64Array, s: number, e: number) => {
        pdf.sampleBatch(u, x, p, s, e);
        p.fill(0, s, e);
      },
    };
    const bad = new EstimateRun1D({ f, pdf: broken, sequence: 'sobol', seed: 1 }, 10);
    expect(bad.step()).toBe(true);
    expect(bad.result().invalid).toBe(10);
    expect(Number.isNaN(bad.result().estimate)).toBe(true);
  });
});

describe('ConvergenceRun1D and convergence rates', () => {
  it('records every checkpoint in resumable steps; stratified uses one set per N', () => {
    const cps = logSpacedCounts(5000, 4, 10);
    for (const sequence of SEQUENCE_KINDS) {
      const run = new ConvergenceRun1D({ f, pdf: uniformPdf1D(0, 2), sequence, seed: 2 }, cps, I);
      let steps = 0;
      while (!run.step(777)) steps++;
      expect(steps).toBeGreaterThan(2);
      expect(run.done).toBe(run.total);
      expect(run.series.recorded).toBe(cps.length);
      for (let k = 0; k < cps.length; k++) expect(Number.isFinite(run.series.estimate[k])).toBe(true);
      // the last checkpoint equals a direct estimate with N_max points of the same set
      const direct = estimate1D({ f, pdf: uniformPdf1D(0, 2), sequence, seed: 2 }, 5000);
      expect(run.series.estimate[cps.length - 1]).toBeCloseTo(direct.estimate, 10);
    }
  });

  it('RMSE slopes: independent ≈ −1/2, stratified ≈ −3/2, Sobol/Halton steeper than −0.8', () => {
    const cps = logSpacedCounts(4096, 3, 16);
    const slope = (sequence: SequenceKind) => {
      const acc = new RmseAccumulator(cps, I, 64);
      for (let r = 0; r < 64; r++) {
        const run = new ConvergenceRun1D({ f, pdf: uniformPdf1D(0, 2), sequence, seed: 1000 + r }, cps, I);
        acc.addRun(run.runAll());
      }
      const s = acc.summary();
      return fitLogLogSlope(s.n, s.rmse).slope;
    };
    expect(Math.abs(slope('independent') + 0.5)).toBeLessThan(0.12);
    // jittered 1D stratification of a smooth f: variance O(N^-3), RMSE O(N^-1.5)
    expect(Math.abs(slope('stratified') + 1.5)).toBeLessThan(0.15);
    expect(slope('sobol')).toBeLessThan(-0.8);
    expect(slope('halton')).toBeLessThan(-0.8);
  });
});
