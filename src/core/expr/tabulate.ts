/**
 * Batch evaluation of compiled expressions into Float64Arrays (caller-owned or new), for tabulated
 * densities and plots. Pure, no allocation per point.
 */

/** A uniform 1D grid of `count` points on [min, max]: cell centres (default) or the count edges. */
export interface Grid1D {
  min: number;
  max: number;
  count: number;
  /** 'center': x_i = min + (i + ½)Δ, Δ = (max − min)/count (midpoints, for tabulating densities);
   *  'edge': x_i = min + i·(max − min)/(count − 1) (both ends included, for plots). */
  at?: 'center' | 'edge';
}

/** The i-th coordinate of a grid. */
export function gridPoint(g: Grid1D, i: number): number {
  if (g.at === 'edge') return g.count > 1 ? g.min + (i * (g.max - g.min)) / (g.count - 1) : g.min;
  return g.min + ((i + 0.5) * (g.max - g.min)) / g.count;
}

/** Evaluate fn(x) at the points of a 1D grid into out[0 … count − 1]. */
export function tabulate1D(fn: (x: number) => number, grid: Grid1D, out: Float64Array = new Float64Array(grid.count)): Float64Array {
  for (let i = 0; i < grid.count; i++) out[i] = fn(gridPoint(grid, i));
  return out;
}

/**
 * Evaluate fn(x, y) on a 2D grid into out, row-major with y rows: out[j·nx + i] = fn(x_i, y_j).
 * (For a density in (θ, φ) tabulated for PiecewiseConstant2D with u = φ columns and v = θ rows,
 * pass x = φ grid and y = θ grid and call fn as (φ, θ) → p(θ, φ).)
 */
export function tabulate2D(
  fn: (x: number, y: number) => number,
  x: Grid1D,
  y: Grid1D,
  out: Float64Array = new Float64Array(x.count * y.count),
): Float64Array {
  const xs = new Float64Array(x.count);
  for (let i = 0; i < x.count; i++) xs[i] = gridPoint(x, i);
  for (let j = 0; j < y.count; j++) {
    const yj = gridPoint(y, j);
    const row = j * x.count;
    for (let i = 0; i < x.count; i++) out[row + i] = fn(xs[i]!, yj);
  }
  return out;
}

/**
 * Evaluate a compiled expression on a 1D or 2D grid (see {@link tabulate1D}, {@link tabulate2D}).
 */
export function tabulateExpression(fn: (...v: number[]) => number, x: Grid1D, y?: Grid1D, out?: Float64Array): Float64Array {
  return y ? tabulate2D(fn, x, y, out) : tabulate1D(fn, x, out);
}

/** Summary of a table: the first non-finite and negative entries (−1 if none), min, max. */
export function scanTable(values: ArrayLike<number>): { firstNonFinite: number; firstNegative: number; min: number; max: number } {
  let firstNonFinite = -1;
  let firstNegative = -1;
  let min = Infinity;
  let max = -Infinity;
  for (let i = 0; i < values.length; i++) {
    const v = values[i]!;
    if (!Number.isFinite(v)) {
      if (firstNonFinite < 0) firstNonFinite = i;
      continue;
    }
    if (v < 0 && firstNegative < 0) firstNegative = i;
    if (v < min) min = v;
    if (v > max) max = v;
  }
  return { firstNonFinite, firstNegative, min, max };
}
