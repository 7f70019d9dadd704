/**
 * Numerical integration used to turn a pdf into expected bin counts for the χ² tests.
 * Pure functions, no allocation per evaluation.
 */

const glCache = new Map<number, { x: Float64Array; w: Float64Array }>();

/** P_n(z) and P_n′(z) by the three-term recurrence (|z| < 1). */
function legendre(n: number, z: number): [number, number] {
  let p1 = 1;
  let p2 = 0;
  for (let j = 0; j < n; j++) {
    const p3 = p2;
    p2 = p1;
    p1 = ((2 * j + 1) * z * p2 - j * p3) / (j + 1);
  }
  return [p1, (n * (z * p1 - p2)) / (z * z - 1)];
}

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
    for (let iter = 0; iter < 100; iter++) {
      const z1 = z;
      const [p, dp] = legendre(n, z1);
      z = z1 - p / dp;
      if (Math.abs(z - z1) < 1e-15) break;
    }
    // the derivative at the converged node gives the weight
    const pp = legendre(n, z)[1];
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
    const xi = cx + hx * x[i];
    let row = 0;
    for (let j = 0; j < x.length; j++) row += w[j] * f(xi, cy + hy * x[j]);
    s += w[i] * row;
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
  /**
   * Maximum refinement depth in levels of 2 × 2 subdivision (default 12): a cell may be bisected at
   * most 2·maxDepth times in all (e.g. down to 2^-maxDepth of the domain along each axis, or
   * further along one axis when only that one needs it).
   */
  maxDepth?: number;
  /** Maximum number of integrand evaluations (default 400 000): bounds the work in every case. */
  maxEvals?: number;
  /**
   * Filled in on return (2D adaptive only): `error`, the summed |change under halving| over the final
   * cells, those at the depth limit included (a divergent integral keeps a large error there), and
   * `resolved`, whether that error met the tolerance. Not filled when the result is not finite.
   */
  report?: { error: number; resolved: boolean };
}

/**
 * ∫∫ f(x, y) dx dy over [x0,x1]×[y0,y1] by globally adaptive quadrature. Each cell carries its
 * Gauss–Legendre estimate and the two estimates from halving it along x and along y; the axis where
 * halving changed the estimate most (where f is least smooth) is its split axis and that change its
 * error estimate. The cell with the largest error is split first, until the summed error is within
 * tolerance, every cell has reached the depth limit, or the evaluation budget is spent (the
 * best estimate so far is returned). Anisotropic bisection resolves edge singularities such as
 * cos^n θ with n → 0 at cos θ = 0, and tabulated (discontinuous) densities, with bounded work.
 * Measure: Lebesgue measure dx dy of the rectangle.
 * Source: globally adaptive cubature after Genz & Malik (1980) / QUADPACK's error-ordered
 * subdivision (Piessens et al. 1983), with tensor Gauss–Legendre rules.
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
  const maxDepth = 2 * (opts.maxDepth ?? 12); // in bisections
  const absTol = opts.absTol ?? 1e-13 * Math.abs((x1 - x0) * (y1 - y0));
  const perCell = 4 * order * order;
  let evalsLeft = (opts.maxEvals ?? 400000) - order * order;
  const whole = gaussLegendre2D(f, x0, x1, y0, y1, order);
  if (!Number.isFinite(whole)) return whole;

  const cells: Cell[] = [];
  const heap: number[] = []; // indices into cells, max-heap on error
  const push = (c: Cell) => {
    cells.push(c);
    heap.push(cells.length - 1);
    let i = heap.length - 1;
    while (i > 0) {
      const p = (i - 1) >> 1;
      if (cells[heap[p]].err >= cells[heap[i]].err) break;
      [heap[p], heap[i]] = [heap[i], heap[p]];
      i = p;
    }
  };
  const pop = (): Cell => {
    const top = cells[heap[0]];
    const last = heap.pop()!;
    if (heap.length > 0) {
      heap[0] = last;
      let i = 0;
      for (;;) {
        const l = 2 * i + 1;
        const r = l + 1;
        let m = i;
        if (l < heap.length && cells[heap[l]].err > cells[heap[m]].err) m = l;
        if (r < heap.length && cells[heap[r]].err > cells[heap[m]].err) m = r;
        if (m === i) break;
        [heap[m], heap[i]] = [heap[i], heap[m]];
        i = m;
      }
    }
    return top;
  };
  const analyse = (ax: number, bx: number, ay: number, by: number, est: number, depth: number): Cell => {
    evalsLeft -= perCell;
    const xm = 0.5 * (ax + bx);
    const ym = 0.5 * (ay + by);
    const a = gaussLegendre2D(f, ax, xm, ay, by, order);
    const b = gaussLegendre2D(f, xm, bx, ay, by, order);
    const c = gaussLegendre2D(f, ax, bx, ay, ym, order);
    const d = gaussLegendre2D(f, ax, bx, ym, by, order);
    const ex = Math.abs(a + b - est);
    const ey = Math.abs(c + d - est);
    const splitX = ex >= ey;
    return {
      x0: ax,
      x1: bx,
      y0: ay,
      y1: by,
      depth,
      splitX,
      lo: splitX ? a : c,
      hi: splitX ? b : d,
      best: splitX ? a + b : c + d,
      err: depth >= maxDepth ? 0 : Math.max(ex, ey),
      rawErr: Math.max(ex, ey),
    };
  };

  let root = analyse(x0, x1, y0, y1, whole, 0);
  if (!Number.isFinite(root.best)) return root.best;
  push(root);
  let total = root.best;
  let errSum = root.err;
  while (heap.length > 0 && evalsLeft >= 2 * perCell) {
    if (errSum <= Math.max(absTol, relTol * Math.abs(total))) break;
    const c = pop();
    if (c.err === 0) {
      push(c);
      break;
    }
    const xm = 0.5 * (c.x0 + c.x1);
    const ym = 0.5 * (c.y0 + c.y1);
    const k1 = c.splitX
      ? analyse(c.x0, xm, c.y0, c.y1, c.lo, c.depth + 1)
      : analyse(c.x0, c.x1, c.y0, ym, c.lo, c.depth + 1);
    const k2 = c.splitX
      ? analyse(xm, c.x1, c.y0, c.y1, c.hi, c.depth + 1)
      : analyse(c.x0, c.x1, ym, c.y1, c.hi, c.depth + 1);
    if (!Number.isFinite(k1.best) || !Number.isFinite(k2.best)) return k1.best + k2.best;
    total += k1.best + k2.best - c.best;
    errSum += k1.err + k2.err - c.err;
    push(k1);
    push(k2);
    c.err = -1; // retired (no longer a leaf)
  }
  // sum the leaves afresh (no drift from the running updates)
  let sum = 0;
  let rawErr = 0;
  for (const i of heap) {
    sum += cells[i].best;
    rawErr += cells[i].rawErr;
  }
  root = cells[0];
  if (opts.report) {
    const value = heap.length > 0 ? sum : root.best;
    opts.report.error = rawErr;
    opts.report.resolved = rawErr <= Math.max(absTol, relTol * Math.abs(value));
  }
  return heap.length > 0 ? sum : root.best;
}

interface Cell {
  x0: number;
  x1: number;
  y0: number;
  y1: number;
  depth: number;
  splitX: boolean;
  /** estimates of the two halves along the split axis, and their sum */
  lo: number;
  hi: number;
  best: number;
  /** error estimate: |change of the estimate when halved along the split axis| (0 at max depth) */
  err: number;
  /** the same change, also at max depth */
  rawErr: number;
}
