/**
 * Drivers that turn a 1D density, a point sequence and an integrand into estimates and convergence
 * series, in fixed-size batches over caller-reusable typed arrays (no object per sample). They are
 * resumable (`step(budget)`), so a worker can interleave progress messages and cancellation.
 *
 * Estimator: ⟨I⟩ = 1/N Σ f(xᵢ)/p(xᵢ), xᵢ = P⁻¹(uᵢ) with uᵢ from the sequence (pbrt-v4 §2.2).
 * Sequences: src/core/random `fillSequence1D` (independent, stratified, Halton, Sobol).
 * A stratified set's prefix is not stratified, so for 'stratified' each checkpoint N is estimated
 * from its own N-point set (cost Σ N_k instead of N_max); the other sequences are progressive and
 * one stream serves every checkpoint.
 */
import { fillSequence1D, type SequenceKind } from '../random/sequences';
import type { Pdf1D } from '../sampling/pdf1d';
import { ConvergenceSeries } from './convergence';
import { Welford } from './welford';
import { finishEstimate, type McEstimate } from './estimate';

/** Samples per batch. */
export const BATCH = 4096;

/** Reusable work buffers for the drivers. */
export class Batch1D {
  readonly u = new Float64Array(BATCH);
  readonly x = new Float64Array(BATCH);
  readonly p = new Float64Array(BATCH);
  readonly y = new Float64Array(BATCH);
}

/** What to integrate and how: ∫ f dx over the pdf's [a, b], with points from the sequence. */
export interface Problem1D {
  f: (x: number) => number;
  pdf: Pdf1D;
  sequence: SequenceKind;
  seed: number;
}

/**
 * Terms yᵢ = f(xᵢ)/p(xᵢ) for points [start, end) of the n-point set, written to buf.y[0 .. end − start).
 * f = 0 gives 0; p = 0 with f ≠ 0, or a non-finite f, gives NaN (the callers count these as invalid).
 */
export function fillTerms(prob: Problem1D, n: number, start: number, end: number, buf: Batch1D): void {
  const m = end - start;
  const { u, x, p, y } = buf;
  fillSequence1D(prob.sequence, prob.seed, n, u, start, end, 0);
  prob.pdf.sampleBatch(u, x, p, 0, m);
  const f = prob.f;
  for (let i = 0; i < m; i++) {
    const fx = f(x[i]);
    const pi = p[i];
    y[i] = fx === 0 ? 0 : pi > 0 && Number.isFinite(fx) ? fx / pi : NaN;
  }
}

/**
 * Estimate ∫ f dx with exactly n points of the problem's sequence (n ≥ 1). Batched; standard error
 * from the Welford variance of the terms (for QMC sequences this is the i.i.d. formula, an upper
 * bound in practice, not a confidence interval).
 */
export function estimate1D(prob: Problem1D, n: number, buf = new Batch1D()): McEstimate {
  const w = new Welford();
  let invalid = 0;
  for (let s = 0; s < n; s += BATCH) {
    const e = Math.min(n, s + BATCH);
    fillTerms(prob, n, s, e, buf);
    for (let i = 0; i < e - s; i++) {
      const y = buf.y[i];
      if (Number.isFinite(y)) w.add(y);
      else invalid++;
    }
  }
  return finishEstimate(w, invalid);
}

/**
 * {@link estimate1D} in steps of one batch (BATCH points), so a page can spread it over several
 * short tasks; the same arithmetic in the same order, so `result()` equals estimate1D(prob, n)
 * exactly once `step()` has returned true.
 */
export class EstimateRun1D {
  private w = new Welford();
  private invalid = 0;
  private s = 0;

  constructor(
    readonly prob: Problem1D,
    readonly n: number,
    private buf = new Batch1D(),
  ) {}

  /** Process the next batch; returns true when all n points are in. */
  step(): boolean {
    const { n, buf, w } = this;
    if (this.s < n) {
      const s = this.s;
      const e = Math.min(n, s + BATCH);
      fillTerms(this.prob, n, s, e, buf);
      for (let i = 0; i < e - s; i++) {
        const y = buf.y[i];
        if (Number.isFinite(y)) w.add(y);
        else this.invalid++;
      }
      this.s = e;
    }
    return this.s >= n;
  }

  /** The estimate of the points processed so far (all n once step() has returned true). */
  result(): McEstimate {
    const w = this.w;
    return {
      n: w.count,
      estimate: w.count > 0 ? w.mean : NaN,
      variance: w.variance(),
      stderr: w.standardError(),
      invalid: this.invalid,
    };
  }
}

/**
 * A resumable convergence run: call `step(budget)` until it returns true; `series` fills in as the
 * checkpoints are passed. `done` counts the samples drawn so far, `total` the samples needed.
 */
export class ConvergenceRun1D {
  readonly series: ConvergenceSeries;
  readonly total: number;
  done = 0;
  private k = 0;
  private pos = 0;
  private w = new Welford();
  private invalidInSet = 0;

  constructor(
    readonly prob: Problem1D,
    checkpoints: ArrayLike<number>,
    exact: number,
    private buf = new Batch1D(),
  ) {
    this.series = new ConvergenceSeries(checkpoints, exact);
    const cps = this.series.n;
    let t = 0;
    if (prob.sequence === 'stratified') for (const c of cps) t += c;
    else t = cps.length ? cps[cps.length - 1] : 0;
    this.total = t;
  }

  /** Process about `budget` samples; returns true when every checkpoint is recorded. */
  step(budget: number): boolean {
    const cps = this.series.n;
    const K = cps.length;
    let left = Math.max(1, budget);
    if (this.prob.sequence !== 'stratified') {
      const nMax = K ? cps[K - 1] : 0;
      while (left > 0 && this.pos < nMax) {
        const e = Math.min(nMax, this.pos + Math.min(BATCH, left));
        fillTerms(this.prob, nMax, this.pos, e, this.buf);
        this.series.push(this.buf.y, 0, e - this.pos);
        left -= e - this.pos;
        this.done += e - this.pos;
        this.pos = e;
      }
      return this.pos >= nMax;
    }
    // stratified: one full n_k-point set per checkpoint
    while (left > 0 && this.k < K) {
      const n = cps[this.k];
      const e = Math.min(n, this.pos + Math.min(BATCH, left));
      fillTerms(this.prob, n, this.pos, e, this.buf);
      for (let i = 0; i < e - this.pos; i++) {
        const y = this.buf.y[i];
        if (Number.isFinite(y)) this.w.add(y);
        else this.invalidInSet++;
      }
      left -= e - this.pos;
      this.done += e - this.pos;
      this.pos = e;
      if (this.pos >= n) {
        this.series.record(this.k, this.w.count ? this.w.mean : NaN, this.w.standardError());
        this.series.invalid += this.invalidInSet;
        this.invalidInSet = 0;
        this.w.reset();
        this.pos = 0;
        this.k++;
      }
    }
    return this.k >= K;
  }

  /** Run to the end in one go. */
  runAll(): ConvergenceSeries {
    while (!this.step(1 << 20));
    return this.series;
  }
}
