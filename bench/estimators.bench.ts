/**
 * Throughput of the Monte Carlo estimators (core/estimators) on the exam's Q4 integral
 * ∫₀² (x + 2)² dx: the batched drivers (sequence → warp → f/p → Welford, over reused
 * Float64Arrays) beside a naive per-sample version that builds one object per sample and sums with
 * Array methods, plus the convergence series and the Welford update alone.
 * Run: npx vitest bench --run bench/estimators.bench.ts
 */
import { bench, describe } from 'vitest';
import { Batch1D, ConvergenceSeries, estimate1D, logSpacedCounts, Welford } from '../src/core/estimators';
import { squarePdf1D, uniformPdf1D, linearPdf1D } from '../src/core/sampling/pdf1d';
import { Rng } from '../src/core/random';

const N = 100_000;
const f = (x: number) => (x + 2) * (x + 2);
const buf = new Batch1D();
const uniform = uniformPdf1D(0, 2);
const square = squarePdf1D(0, 2, 2);
const linear = linearPdf1D(0, 2, 4, 16);
const terms = new Rng(5).fill(new Float64Array(N));
const cps = logSpacedCounts(N, 10);
let sink = 0;

describe(`Monte Carlo estimators on Q4, ${N} samples per iteration`, () => {
  bench('estimate1D uniform · independent (batched)', () => {
    sink += estimate1D({ f, pdf: uniform, sequence: 'independent', seed: 1 }, N, buf).estimate;
  });
  bench('estimate1D linear · independent (batched)', () => {
    sink += estimate1D({ f, pdf: linear, sequence: 'independent', seed: 1 }, N, buf).estimate;
  });
  bench('estimate1D p ∝ f · independent (batched)', () => {
    sink += estimate1D({ f, pdf: square, sequence: 'independent', seed: 1 }, N, buf).estimate;
  });
  bench('estimate1D uniform · sobol (batched)', () => {
    sink += estimate1D({ f, pdf: uniform, sequence: 'sobol', seed: 1 }, N, buf).estimate;
  });
  bench('naive: one object per sample, Array.map/reduce', () => {
    const rng = new Rng(1);
    const samples: { x: number; fx: number; p: number }[] = [];
    for (let i = 0; i < N; i++) {
      const x = 2 * rng.nextFloat();
      samples.push({ x, fx: f(x), p: 0.5 });
    }
    const ys = samples.map((s) => s.fx / s.p);
    const mean = ys.reduce((a, b) => a + b, 0) / ys.length;
    const v = ys.reduce((a, y) => a + (y - mean) ** 2, 0) / (ys.length - 1);
    sink += mean + v;
  });
});

describe(`running statistics, ${N} samples per iteration`, () => {
  bench('Welford.addArray (batched)', () => {
    const w = new Welford();
    w.addArray(terms);
    sink += w.mean;
  });
  bench('Welford.add per value', () => {
    const w = new Welford();
    for (let i = 0; i < N; i++) w.add(terms[i]);
    sink += w.mean;
  });
  bench('ConvergenceSeries.push (10 checkpoints per decade)', () => {
    const s = new ConvergenceSeries(cps, 0.5);
    s.push(terms);
    sink += s.estimate[0];
  });
});

export { sink };
