/** The race's histograms: every sample drawn so far, binned over [a, b], per lane. */
import type { Pdf1D } from '../../core/sampling/pdf1d';

/** Bins of the race's histograms over [a, b]. */
export const RACE_BINS = 24;

/**
 * The bin of each sample: ⌊(x − a)/(b − a) · bins⌋, the last bin closed at b (a sample outside
 * [a, b], which no sampler of the scene produces, goes to the nearest end bin). Once per track.
 */
export function raceBinIndex(xs: ArrayLike<number>, a: number, b: number, bins = RACE_BINS): Uint16Array {
  const out = new Uint16Array(xs.length);
  const k = bins / (b - a);
  for (let i = 0; i < xs.length; i++) {
    const j = Math.floor((xs[i] - a) * k);
    out[i] = j < 0 || !(j === j) ? 0 : j >= bins ? bins - 1 : j;
  }
  return out;
}

/** Counts per bin of the first t samples (the histogram of everything drawn so far), into `out`. */
export function raceCounts(
  index: Uint16Array,
  t: number,
  bins = RACE_BINS,
  out: Uint32Array = new Uint32Array(bins),
): Uint32Array {
  out.fill(0);
  const n = Math.max(0, Math.min(index.length, Math.floor(t)));
  for (let i = 0; i < n; i++) out[index[i]]++;
  return out;
}

/** Bin k's interval [lo, hi] over [a, b]. */
export function binRange(k: number, a: number, b: number, bins = RACE_BINS): [number, number] {
  const w = (b - a) / bins;
  return [a + k * w, k === bins - 1 ? b : a + (k + 1) * w];
}

/** How many of the first t samples lie in [lo, hi]. */
export function countIn(xs: ArrayLike<number>, t: number, lo: number, hi: number): number {
  let c = 0;
  const n = Math.max(0, Math.min(xs.length, Math.floor(t)));
  for (let i = 0; i < n; i++) if (xs[i] >= lo && xs[i] <= hi) c++;
  return c;
}

/**
 * The half of [a, b] where a pdf puts more than half of its mass (where importance samples crowd),
 * from its CDF at the midpoint; the right half when they are equal.
 */
export function heavierHalf(pdf: Pick<Pdf1D, 'invert'>, a: number, b: number): [number, number] {
  const m = (a + b) / 2;
  return pdf.invert(m) > 0.5 ? [a, m] : [m, b];
}
