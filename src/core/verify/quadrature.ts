/**
 * Numerical integration used to turn a pdf into expected bin counts for the χ² tests.
 * Pure functions, no allocation per evaluation.
 */

const glCache = new Map<number, { x: Float64Array; w: Float64Array }>();

/**
 * Gauss–Legendre nodes and weights on [−1, 1] for `order` points (1 ≤ order ≤ 64), computed by
 * Newton's iteration on the Legendre recurrence (exact for polynomials of degree ≤ 2·order − 1).
 * Source: Numerical Recipes 3rd ed. §4.6 (`gauleg`); Golub & Welsch (1969).
 */
export function gaussLegendre(order: number): { x: Float64Array; w: Float64Array } {
  const n = Math.max(1, Math.min(64, Math.floor(order)));
  const cached = glCache.get(n);
  if (cached) return cached;
  const x = new Float64Array(n);
  const w = new Float64Array(n);
  const m = (n + 1) >> 1;
  for (let i = 0; i < m; i++) {
    let z = Math.cos((Math.PI * (i + 0.75)) / (n + 0.5));
    let pp = 0;
    for (let iter = 0; iter < 100; iter++) {
      let p1 = 1;
      let p2 = 0;
      for (let j = 0; j < n; j++) {
        const p3 = p2;
        p2 = p1;
        p1 = ((2 * j + 1) * z * p2 - j * p3) / (j + 1);
      }
      pp = (n * (z * p1 - p2)) / (z * z - 1);
      const z1 = z;
      z = z1 - p1 / pp;
      if (Math.abs(z - z1) < 1e-15) break;
    }
    // recompute the derivative at the converged node for the weight
    let p1 = 1;
    let p2 = 0;
    for (let j = 0; j < n; j++) {
      const p3 = p2;
      p2 = p1;
      p1 = ((2 * j + 1) * z * p2 - j * p3) / (j + 1);
    }
    pp = (n * (z * p1 - p2)) / (z * z - 1);
    x[i] = -z;
    x[n - 1 - i] = z;
    w[i] = w[n - 1 - i] = 2 / ((1 - z * z) * pp * pp);
  }
  if (n % 2 === 1) x[m - 1] = 0;
  const r = { x, w };
  glCache.set(n, r);
  return r;
}

/** Tensor-product Gauss–Legendre rule of the given order over the rectangle [x0,x1]×[y0,y1]. */
export function gaussLegendre2D(
  f: (x: number, y: number) => number,
  x0: number,
  x1: number,
  y0: number,
  y1: number,
  order = 7,
): number {
  const { x, w } = gaussLegendre(order);
  const hx = 0.5 * (x1 - x0);
  const cx = 0.5 * (x1 + x0);
  const hy = 0.5 * (y1 - y0);
  const cy = 0.5 * (y1 + y0);
  let s = 0;
  for (let i = 0; i < x.length; i++) {
    const xi = cx + hx * x[i]!;
    let row = 0;
    for (let j = 0; j < x.length; j++) row += w[j]! * f(xi, cy + hy * x[j]!);
    s += w[i]! * row;
  }
  return s * hx * hy;
}

/** Options of {@link adaptiveIntegrate2D}. */
export interface AdaptiveOptions {
  /** Gauss–Legendre order per cell (default 7). */
  order?: number;
  /** Relative tolerance (default 1e-10). */
  relTol?: number;
  /** Absolute tolerance (default 1e-13 × cell area). */
  absTol?: number;
  /** Maximum number of 2×2 subdivisions (default 5): bounds the work for discontinuous integrands. */
  maxDepth?: number;
}

/**
 * ∫∫ f(x, y) dx dy over [x0,x1]×[y0,y1] by adaptive quadrature: a cell's Gauss–Legendre estimate is
 * compared with the sum over its four quarters; cells that disagree by more than the tolerance are
 * split, up to `maxDepth` times (so the cost is bounded even for a discontinuous f, such as a
 * tabulated piecewise-constant pdf). Measure: Lebesgue measure dx dy of the rectangle.
 * Source: standard adaptive cubature (e.g. Genz & Malik 1980, simplified to tensor Gauss rules).
 */
export function adaptiveIntegrate2D(
  f: (x: number, y: number) => number,
  x0: number,
  x1: number,
  y0: number,
  y1: number,
  opts: AdaptiveOptions = {},
): number {
  const order = opts.order ?? 7;
  const relTol = opts.relTol ?? 1e-10;
  const maxDepth = opts.maxDepth ?? 5;
  const absTol = opts.absTol ?? 1e-13 * Math.abs((x1 - x0) * (y1 - y0));
  const whole = gaussLegendre2D(f, x0, x1, y0, y1, order);
  return refine(f, x0, x1, y0, y1, whole, order, relTol, absTol, maxDepth);
}

function refine(
  f: (x: number, y: number) => number,
  x0: number,
  x1: number,
  y0: number,
  y1: number,
  whole: number,
  order: number,
  relTol: number,
  absTol: number,
  depth: number,
): number {
  const xm = 0.5 * (x0 + x1);
  const ym = 0.5 * (y0 + y1);
  const a = gaussLegendre2D(f, x0, xm, y0, ym, order);
  const b = gaussLegendre2D(f, xm, x1, y0, ym, order);
  const c = gaussLegendre2D(f, x0, xm, ym, y1, order);
  const d = gaussLegendre2D(f, xm, x1, ym, y1, order);
  const parts = a + b + c + d;
  if (!Number.isFinite(parts)) return parts;
  if (depth <= 0 || Math.abs(parts - whole) <= Math.max(absTol, relTol * Math.abs(parts))) return parts;
  const at = absTol / 4;
  return (
    refine(f, x0, xm, y0, ym, a, order, relTol, at, depth - 1) +
    refine(f, xm, x1, y0, ym, b, order, relTol, at, depth - 1) +
    refine(f, x0, xm, ym, y1, c, order, relTol, at, depth - 1) +
    refine(f, xm, x1, ym, y1, d, order, relTol, at, depth - 1)
  );
}
