/**
 * Least-squares fit of log y = c + s · log x (base 10): the convergence rate s of an error curve
 * |error| ∝ N^s (s ≈ −½ for Monte Carlo, ≈ −1 for good QMC on smooth integrands).
 * Source: ordinary least squares (e.g. Press et al., Numerical Recipes §15.2). Points where x or y is
 * not finite and positive are skipped (an exact hit, error 0, has no logarithm).
 */
export interface SlopeFit {
  /** Fitted exponent s. NaN if fewer than two usable points or all x equal. */
  slope: number;
  /** Fitted log10 intercept c. */
  intercept: number;
  /** Coefficient of determination R² of the log-log fit. */
  r2: number;
  /** Points used. */
  points: number;
}

/** Fit log10(y) against log10(x) over [start, end) (see module doc). */
export function fitLogLogSlope(
  x: ArrayLike<number>,
  y: ArrayLike<number>,
  start = 0,
  end = Math.min(x.length, y.length),
): SlopeFit {
  // The logarithms of the usable points, in order (each computed once).
  const lx: number[] = [];
  const ly: number[] = [];
  for (let i = start; i < end; i++) {
    const xi = x[i];
    const yi = y[i];
    if (!(xi > 0 && yi > 0 && xi < Infinity && yi < Infinity)) continue;
    lx.push(Math.log10(xi));
    ly.push(Math.log10(yi));
  }
  const n = lx.length;
  if (n < 2) return { slope: NaN, intercept: NaN, r2: NaN, points: n };
  let sx = 0;
  let sy = 0;
  for (let k = 0; k < n; k++) {
    sx += lx[k];
    sy += ly[k];
  }
  const mx = sx / n;
  const my = sy / n;
  let sxx = 0;
  let sxy = 0;
  let syy = 0;
  for (let k = 0; k < n; k++) {
    const dx = lx[k] - mx;
    const dy = ly[k] - my;
    sxx += dx * dx;
    sxy += dx * dy;
    syy += dy * dy;
  }
  if (sxx === 0) return { slope: NaN, intercept: NaN, r2: NaN, points: n };
  const slope = sxy / sxx;
  const r2 = syy === 0 ? 1 : (sxy * sxy) / (sxx * syy);
  return { slope, intercept: my - slope * mx, r2, points: n };
}
