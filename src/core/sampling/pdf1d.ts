/**
 * One-dimensional densities on an interval [a, b] as sample / pdf / invert triples, for the Monte
 * Carlo scene (exam Q4): uniform, a linear ramp, p ∝ (x + c)² (exactly proportional to the exam's
 * f(x) = (x + 2)² for c = 2), p ∝ any tabulated f ≥ 0, and a user-typed pdf (normalized numerically,
 * validated).
 *
 * Measure: every pdf here is a density with respect to dx on [a, b] (∫ₐᵇ p dx = 1); pdfs return 0
 * outside [a, b], never NaN. Samplers map u ∈ [0, 1) into [a, b] monotonically, and
 * invert(sample(u)) ≈ u. Domain of the interval: finite a < b.
 * Source: pbrt-v4 `util/sampling.h` (SampleLinear / LinearPDF / InvertLinearSample) and §A.1
 * (the inversion method); pbrt-v4 §A.4.1 for tabulated piecewise-constant distributions.
 */
import { formatPlain } from '../format';
import type { Failure } from '../failure';
import { integrate1D } from '../verify/integrate1d';
import { gaussLegendre } from '../verify/quadrature';
import { PiecewiseConstant1D } from './piecewise1D';

/** A 1D density on [a, b] with its sampler and inverse (the scene's strategies are these). */
export interface Pdf1D {
  /** Short name of the density (uniform, linear, square, tabulated, custom). */
  readonly kind: string;
  readonly a: number;
  readonly b: number;
  /** x = P⁻¹(u) for u ∈ [0, 1); result in [a, b]. */
  sample(u: number): number;
  /** p(x) w.r.t. dx; 0 outside [a, b]. This is the density the samples really have. */
  pdf(x: number): number;
  /** u = P(x) ∈ [0, 1] (the CDF); clamps x to [a, b]. */
  invert(x: number): number;
  /**
   * Batched sampler: x[i] = sample(u[i]) and p[i] = pdf(x[i]) for i in [start, end). u and x may be
   * the same buffer. Caller-owned buffers, no allocation.
   */
  sampleBatch(u: Float64Array, x: Float64Array, p: Float64Array, start: number, end: number): void;
}

const clamp = (x: number, lo: number, hi: number): number => (x < lo ? lo : x > hi ? hi : x);

// ---------------------------------------------------------------------------------------------
// Uniform

/**
 * Uniform sample on [a, b]: x = a + u (b − a), clamped into [a, b]. Domain u ∈ [0, 1).
 * Density {@link uniform1DPdf}. Source: pbrt-v4 `SampleUniform…` family (inversion of a linear CDF).
 */
export function sampleUniform1D(u: number, a: number, b: number): number {
  return clamp(a + u * (b - a), a, b);
}

/** Density of {@link sampleUniform1D}: 1/(b − a) on [a, b], 0 outside (measure dx). */
export function uniform1DPdf(x: number, a: number, b: number): number {
  return x >= a && x <= b ? 1 / (b - a) : 0;
}

/** Inverse of {@link sampleUniform1D}: u = (x − a)/(b − a), clamped to [0, 1]. */
export function invertUniform1DSample(x: number, a: number, b: number): number {
  return clamp((x - a) / (b - a), 0, 1);
}

// ---------------------------------------------------------------------------------------------
// Linear ramp

/**
 * Sample the linear ramp on [a, b] whose (unnormalized) density is w₀ at a and w₁ at b:
 * p(x) ∝ (1 − t) w₀ + t w₁ with t = (x − a)/(b − a). Domain: w₀, w₁ ≥ 0, not both 0; u ∈ [0, 1).
 * Uses pbrt-v4's cancellation-free form t = u (w₀ + w₁) / (w₀ + √lerp(u, w₀², w₁²)).
 * Density {@link linear1DPdf}. Source: pbrt-v4 `SampleLinear` (util/sampling.h), §A.1.
 *
 * The scene's "linear" strategy uses w₀ = |f(a)|, w₁ = |f(b)|: the straight line through the
 * integrand's end values, a cheap approximation of p ∝ f for a monotone f (for (x + 2)² on [0, 2]
 * the ramp from 4 to 16).
 */
export function sampleLinear1D(u: number, a: number, b: number, w0: number, w1: number): number {
  if (u === 0 && w0 === 0) return a;
  const t = (u * (w0 + w1)) / (w0 + Math.sqrt((1 - u) * w0 * w0 + u * w1 * w1));
  return clamp(a + Math.min(t, 1) * (b - a), a, b);
}

/** Density of {@link sampleLinear1D}: 2 lerp(t, w₀, w₁) / ((w₀ + w₁)(b − a)); 0 outside [a, b]. */
export function linear1DPdf(x: number, a: number, b: number, w0: number, w1: number): number {
  if (!(x >= a && x <= b)) return 0;
  const t = (x - a) / (b - a);
  return (2 * ((1 - t) * w0 + t * w1)) / ((w0 + w1) * (b - a));
}

/** Inverse of {@link sampleLinear1D}: u = t (w₀ (2 − t) + w₁ t)/(w₀ + w₁) (pbrt `InvertLinearSample`). */
export function invertLinear1DSample(x: number, a: number, b: number, w0: number, w1: number): number {
  const t = clamp((x - a) / (b - a), 0, 1);
  return clamp((t * (w0 * (2 - t) + w1 * t)) / (w0 + w1), 0, 1);
}

// ---------------------------------------------------------------------------------------------
// p ∝ (x + c)²: exactly proportional to the exam's integrand (x + 2)² for c = 2

/** (B³ − A³) computed as (b − a)(B² + AB + A²) with A = a + c, B = b + c: no cancellation. */
function cubeDiff(a: number, b: number, c: number): number {
  const A = a + c;
  const B = b + c;
  return (b - a) * (B * B + A * B + A * A);
}

/**
 * Sample p(x) = 3(x + c)² / ((b + c)³ − (a + c)³) on [a, b] by inverting its CDF:
 * x = ∛((a + c)³ + u((b + c)³ − (a + c)³)) − c. For c = 2 on [0, 2] this is p(x) = (3/56)(x + 2)²,
 * the exam's Q4(c) pdf, and f/p = 56/3 for every sample (zero variance). Domain: u ∈ [0, 1), any
 * finite c (Math.cbrt is monotone on ℝ, so −c inside [a, b] is fine). Density {@link square1DPdf}.
 * Source: inversion method, pbrt-v4 §A.1.
 */
export function sampleSquare1D(u: number, a: number, b: number, c = 2): number {
  const A = a + c;
  return clamp(Math.cbrt(A * A * A + u * cubeDiff(a, b, c)) - c, a, b);
}

/** Density of {@link sampleSquare1D}: 3(x + c)² / ((b + c)³ − (a + c)³) on [a, b], 0 outside. */
export function square1DPdf(x: number, a: number, b: number, c = 2): number {
  if (!(x >= a && x <= b)) return 0;
  const X = x + c;
  return (3 * X * X) / cubeDiff(a, b, c);
}

/** Inverse of {@link sampleSquare1D}: u = ((x + c)³ − (a + c)³)/((b + c)³ − (a + c)³), cancellation-free. */
export function invertSquare1DSample(x: number, a: number, b: number, c = 2): number {
  const xc = clamp(x, a, b);
  return clamp(cubeDiff(a, xc, c) / cubeDiff(a, b, c), 0, 1);
}

// ---------------------------------------------------------------------------------------------
// Pdf1D objects (used by the scene and the estimators)

/** Uniform density on [a, b] as a {@link Pdf1D}. Domain: finite a < b. */
export function uniformPdf1D(a: number, b: number): Pdf1D {
  const inv = 1 / (b - a);
  return {
    kind: 'uniform',
    a,
    b,
    sample: (u) => sampleUniform1D(u, a, b),
    pdf: (x) => uniform1DPdf(x, a, b),
    invert: (x) => invertUniform1DSample(x, a, b),
    sampleBatch(u, x, p, start, end) {
      const w = b - a;
      for (let i = start; i < end; i++) {
        const xi = a + u[i] * w;
        x[i] = xi > b ? b : xi;
        p[i] = inv;
      }
    },
  };
}

/**
 * Linear ramp density (see {@link sampleLinear1D}) as a {@link Pdf1D}. Domain: finite a < b,
 * w₀, w₁ ≥ 0 finite, w₀ + w₁ > 0 (otherwise an Error is thrown).
 */
export function linearPdf1D(a: number, b: number, w0: number, w1: number): Pdf1D {
  if (!(w0 >= 0 && w1 >= 0 && w0 + w1 > 0 && Number.isFinite(w0 + w1))) {
    throw new Error(`linear pdf needs end weights w₀, w₁ ≥ 0, not both 0 (got ${w0}, ${w1})`);
  }
  return {
    kind: 'linear',
    a,
    b,
    sample: (u) => sampleLinear1D(u, a, b, w0, w1),
    pdf: (x) => linear1DPdf(x, a, b, w0, w1),
    invert: (x) => invertLinear1DSample(x, a, b, w0, w1),
    sampleBatch(u, x, p, start, end) {
      const s = w0 + w1;
      const w = b - a;
      const norm = 2 / (s * w);
      const w00 = w0 * w0;
      const w11 = w1 * w1;
      for (let i = start; i < end; i++) {
        const ui = u[i];
        let t = ui === 0 && w0 === 0 ? 0 : (ui * s) / (w0 + Math.sqrt((1 - ui) * w00 + ui * w11));
        if (t > 1) t = 1;
        x[i] = a + t * w;
        p[i] = norm * ((1 - t) * w0 + t * w1);
      }
    },
  };
}

/** Density p ∝ (x + c)² on [a, b] (see {@link sampleSquare1D}) as a {@link Pdf1D}. Domain: finite a < b, c. */
export function squarePdf1D(a: number, b: number, c = 2): Pdf1D {
  const D = cubeDiff(a, b, c);
  const A = a + c;
  const A3 = A * A * A;
  return {
    kind: 'square',
    a,
    b,
    sample: (u) => sampleSquare1D(u, a, b, c),
    pdf: (x) => square1DPdf(x, a, b, c),
    invert: (x) => invertSquare1DSample(x, a, b, c),
    sampleBatch(u, x, p, start, end) {
      const k = 3 / D;
      for (let i = start; i < end; i++) {
        let xi = Math.cbrt(A3 + u[i] * D) - c;
        xi = xi < a ? a : xi > b ? b : xi;
        x[i] = xi;
        const X = xi + c;
        p[i] = k * X * X;
      }
    },
  };
}

// ---------------------------------------------------------------------------------------------
// Typed densities: validation, numerical normalization, tabulated sampling

/** Why a typed density cannot be used as a Monte Carlo pdf. */
export type PdfProblemKind = 'not-finite' | 'negative' | 'not-normalizable' | 'zero' | 'zero-where-f-nonzero';

/** A density that was rejected, with a plain-language message naming the place it fails. */
export interface PdfProblem extends Failure<PdfProblemKind> {
  /** Where it fails, if at a point. */
  readonly x?: number;
}

/** 4-point Gauss–Legendre nodes on [−1, 1] and weights (exact for cubics; used per table bin). */
const { x: GL4_X, w: GL4_W } = gaussLegendre(4);

/** Default number of bins of tabulated densities. */
export const TABLE_BINS = 4096;

/** Result of {@link tabulatedPdf1D}, {@link customPdf1D} and {@link proportionalPdf1D}. */
export type TypedPdfResult =
  | {
      ok: true;
      /** Sampler over the tabulated density q (see {@link tabulatedPdf1D}); q is the density samples really have. */
      pdf: Pdf1D;
      /** The normalized typed density p(x)/Z, exact up to the quadrature of Z; 0 outside [a, b]. */
      density: (x: number) => number;
      /** Z = ∫ₐᵇ p dx of the unnormalized density (adaptive Gauss–Kronrod). */
      norm: number;
    }
  | PdfProblem;

/**
 * Sampler over a piecewise-constant density with the given bin masses on [a, b] (bins of equal
 * width), built on pbrt's PiecewiseConstant1D (./piecewise1D.ts: CDF table, binary search, linear
 * inside the bin) with bin values mass_k/Δx. Domain: masses ≥ 0, finite, not all 0 (throws the
 * table's DensityError otherwise). The density is q(x) = mass_k/(Σ · Δx) in bin k, w.r.t. dx; 0
 * outside [a, b]. Source: pbrt-v4 §A.4.1 `PiecewiseConstant1D` (Sample, Invert), used over bin
 * masses so that each bin carries exactly the mass of the typed density over it.
 */
export function piecewiseConstantPdf1D(
  masses: ArrayLike<number>,
  a: number,
  b: number,
  kind = 'tabulated',
): Pdf1D {
  const n = masses.length;
  const dx = (b - a) / n;
  const values = new Float64Array(n);
  for (let k = 0; k < n; k++) values[k] = masses[k] / dx;
  const table = new PiecewiseConstant1D(values, a, b);
  const dens = table.pdfs;
  return {
    kind,
    a,
    b,
    sample: (u) => table.sample(u).x,
    pdf(x) {
      if (!(x >= a && x <= b)) return 0;
      const s = (x - a) / dx;
      const k = Math.min(n - 1, Math.floor(s));
      // a point on the edge between a full bin and an empty one belongs to the full one (the
      // sampler returns the right edge of bin k − 1 when rounding gives t = 1)
      return dens[k] === 0 && k > 0 && s === k ? dens[k - 1] : dens[k];
    },
    invert: (x) => table.invert(x),
    sampleBatch(u, x, p, start, end) {
      if (start === 0) table.sampleMany(u, x, p, end);
      else
        table.sampleMany(u.subarray(start, end), x.subarray(start, end), p.subarray(start, end), end - start);
    },
  };
}

/**
 * Validate, normalize and tabulate a typed density p on [a, b] (p need not be normalized).
 * Checks, in order, with a message naming the first failing x:
 * - p is not a finite number somewhere on a fine grid (e.g. sqrt(x − 1) below 1) → 'not-finite';
 * - p < 0 somewhere → 'negative' (a density cannot be negative);
 * - ∫ₐᵇ p dx does not converge, or is infinite → 'not-normalizable'; is 0 → 'zero';
 * - f is given and p = 0 where f ≠ 0 → 'zero-where-f-nonzero' (samples never land there, so the
 *   estimator misses that part of the integral: biased, or with infinite variance).
 * The grid is the 4 Gauss–Legendre nodes of each of `bins` equal bins plus both end points.
 *
 * Sampling: each bin receives exactly the mass of p over it (4-point Gauss–Legendre per bin,
 * rescaled to Z); samples follow that piecewise-constant density q, and `pdf.pdf` returns q, the
 * density the samples really have, so an estimator dividing by it stays unbiased. `density`
 * returns the exact normalized p(x)/Z (for given samples and for drawing).
 * Measure dx. Source: pbrt-v4 §A.4.1; QUADPACK for Z.
 */
export function tabulatedPdf1D(
  p: (x: number) => number,
  a: number,
  b: number,
  f?: (x: number) => number,
  bins = TABLE_BINS,
  integrate?: (g: (x: number) => number, a: number, b: number) => { value: number; converged: boolean },
  kind = 'custom',
): TypedPdfResult {
  const fail = (k: PdfProblemKind, message: string, x?: number): TypedPdfResult =>
    x === undefined ? { ok: false, kind: k, message } : { ok: false, kind: k, x, message };
  if (!(Number.isFinite(a) && Number.isFinite(b) && a < b))
    return fail('not-normalizable', `the interval [${a}, ${b}] is empty or not finite`);
  const h = (b - a) / bins;
  const masses = new Float64Array(bins);
  const check = (x: number, v: number): TypedPdfResult | null => {
    if (Number.isNaN(v))
      return fail(
        'not-finite',
        `p(x) is not a number at x = ${formatPlain(x)} (outside the domain of the expression?)`,
        x,
      );
    if (v < 0)
      return fail(
        'negative',
        `p(x) = ${formatPlain(v)} < 0 at x = ${formatPlain(x)}: a density cannot be negative`,
        x,
      );
    if (v === Infinity)
      return fail(
        'not-normalizable',
        `p(x) is infinite at x = ${formatPlain(x)}, so it cannot be normalized here`,
        x,
      );
    if (!Number.isFinite(v)) return fail('not-finite', `p(x) is not finite at x = ${formatPlain(x)}`, x);
    return null;
  };
  let zeroWhereF: number | undefined;
  for (let k = 0; k < bins; k++) {
    const c = a + (k + 0.5) * h;
    let m = 0;
    for (let j = 0; j < 4; j++) {
      const x = c + 0.5 * h * GL4_X[j];
      const v = p(x);
      const bad = check(x, v);
      if (bad) return bad;
      m += GL4_W[j] * v;
      if (v === 0 && f && zeroWhereF === undefined) {
        const fv = f(x);
        if (fv !== 0 && Number.isFinite(fv)) zeroWhereF = x;
      }
    }
    masses[k] = 0.5 * h * m;
  }
  for (const x of [a, b]) {
    const v = p(x);
    if (Number.isNaN(v) || v < 0) {
      const bad = check(x, v);
      if (bad) return bad;
    }
    if (v === 0 && f && zeroWhereF === undefined) {
      const fv = f(x);
      if (fv !== 0 && Number.isFinite(fv)) zeroWhereF = x;
    }
  }
  const integ = integrate ?? defaultIntegrate;
  const Z = integ(p, a, b);
  if (!Number.isFinite(Z.value) || !Z.converged) {
    return fail(
      'not-normalizable',
      `∫ p dx over [${formatPlain(a)}, ${formatPlain(b)}] does not converge: p cannot be normalized into a density`,
    );
  }
  if (!(Z.value > 0))
    return fail(
      'zero',
      `p is zero on all of [${formatPlain(a)}, ${formatPlain(b)}]: there is nothing to sample from`,
    );
  if (zeroWhereF !== undefined) {
    const x = zeroWhereF;
    return fail(
      'zero-where-f-nonzero',
      `p(${formatPlain(x)}) = 0 but f(${formatPlain(x)}) ≠ 0: samples never land where p is zero, so the estimate would miss that part of the integral (biased, or with infinite variance)`,
      x,
    );
  }
  let total = 0;
  for (let k = 0; k < bins; k++) total += masses[k];
  if (!(total > 0))
    return fail('zero', `p is zero on the sampling grid of [${formatPlain(a)}, ${formatPlain(b)}]`);
  const Zv = Z.value;
  return {
    ok: true,
    pdf: piecewiseConstantPdf1D(masses, a, b, kind),
    density: (x) => (x >= a && x <= b ? p(x) / Zv : 0),
    norm: Zv,
  };
}

/** {@link tabulatedPdf1D} as the app calls it: the density p, the interval, the integrand f, the bins. */
type TabulatedPdfBuilder = (
  p: (x: number) => number,
  a: number,
  b: number,
  f?: (x: number) => number,
  bins?: number,
) => TypedPdfResult;

/**
 * A user-typed pdf p on [a, b] (any positive multiple; normalized numerically), validated against
 * the integrand f: {@link tabulatedPdf1D} with its defaults (kind 'custom', Z by adaptive
 * Gauss–Kronrod). Measure dx.
 */
export const customPdf1D: TabulatedPdfBuilder = tabulatedPdf1D;

/**
 * p ∝ |f| on [a, b], tabulated (the zero-variance choice when f does not change sign: f/p is then the
 * constant ∫|f| up to the table's resolution). Fails with 'zero' when f vanishes on [a, b].
 * Measure dx. Source: pbrt-v4 §2.2.2 (importance sampling, p ∝ f is optimal).
 */
export function proportionalPdf1D(
  f: (x: number) => number,
  a: number,
  b: number,
  bins = TABLE_BINS,
): TypedPdfResult {
  const absf = (x: number) => Math.abs(f(x));
  return tabulatedPdf1D(absf, a, b, undefined, bins, undefined, 'proportional');
}

/** Z by adaptive Gauss–Kronrod, to a relative 1e-12 (enough to tell a density from a divergent one). */
function defaultIntegrate(
  g: (x: number) => number,
  a: number,
  b: number,
): { value: number; converged: boolean } {
  const r = integrate1D(g, a, b, { relTol: 1e-12, maxIntervals: 4000 });
  return { value: r.value, converged: r.converged };
}
