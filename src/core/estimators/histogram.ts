/** Equal-width histogram of the finite values (statistics of the Monte Carlo scene's many estimates). */

/** Histogram of values into `bins` equal bins over [lo, hi]. */
export function histogram(
  values: ArrayLike<number>,
  bins: number,
  lo?: number,
  hi?: number,
): { edges: Float64Array; counts: Float64Array } {
  let mn = Infinity;
  let mx = -Infinity;
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    if (!Number.isFinite(v)) continue;
    if (v < mn) mn = v;
    if (v > mx) mx = v;
  }
  lo = lo ?? mn;
  hi = hi ?? mx;
  if (!(hi > lo)) {
    const c = Number.isFinite(lo) ? lo : 0;
    const w = Math.max(1e-12, Math.abs(c) * 1e-9);
    lo = c - w;
    hi = c + w;
  }
  const edges = new Float64Array(bins + 1);
  for (let k = 0; k <= bins; k++) edges[k] = lo + ((hi - lo) * k) / bins;
  const counts = new Float64Array(bins);
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    if (!Number.isFinite(v)) continue;
    const k = Math.min(bins - 1, Math.max(0, Math.floor(((v - lo) / (hi - lo)) * bins)));
    counts[k]++;
  }
  return { edges, counts };
}
