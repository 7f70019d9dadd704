/** The curves of the integrand panel: f and the pdf scaled to f's height, and reading them back. */
import type { Fn1 } from './integral';

/** Curves of f and of the pdf scaled to f's range, on a grid of m points over [a, b]. */
export function curves(
  f: Fn1,
  density: Fn1 | null,
  a: number,
  b: number,
  m = 400,
): { x: Float64Array; f: Float64Array; p: Float64Array; scale: number } {
  const x = new Float64Array(m);
  const fy = new Float64Array(m);
  const py = new Float64Array(m);
  let fmax = 0;
  let pmax = 0;
  for (let i = 0; i < m; i++) {
    const xi = a + ((b - a) * i) / (m - 1);
    x[i] = xi;
    const v = f(xi);
    fy[i] = Number.isFinite(v) ? v : NaN;
    if (Number.isFinite(v)) fmax = Math.max(fmax, Math.abs(v));
    const p = density ? density(xi) : NaN;
    py[i] = p;
    if (Number.isFinite(p)) pmax = Math.max(pmax, p);
  }
  // scale the pdf to the height of f, rounded to a readable factor
  const scale = pmax > 0 && fmax > 0 ? Number((fmax / pmax).toPrecision(3)) : 1;
  for (let i = 0; i < m; i++) py[i] = py[i] * scale;
  return { x, f: fy, p: py, scale };
}

/** The value at x of a function tabulated on an evenly spaced grid (linear interpolation, clamped to its ends). */
export function gridAt(xs: ArrayLike<number>, ys: ArrayLike<number>, x: number): number {
  const n = xs.length;
  if (n < 2) return n ? ys[0] : NaN;
  const x0 = xs[0];
  const x1 = xs[n - 1];
  const q = ((x - x0) / (x1 - x0 || 1)) * (n - 1);
  const k = Math.max(0, Math.min(n - 2, Math.floor(q)));
  const w = q - k;
  return ys[k] * (1 - w) + ys[k + 1] * w;
}
