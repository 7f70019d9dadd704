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
        const xi = a + u[i]! * w;
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
        const ui = u[i]!;
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
        let xi = Math.cbrt(A3 + u[i]! * D) - c;
        xi = xi < a ? a : xi > b ? b : xi;
        x[i] = xi;
        const X = xi + c;
        p[i] = k * X * X;
      }
    },
  };
}
