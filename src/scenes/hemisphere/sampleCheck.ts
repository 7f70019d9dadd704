/**
 * The checks of drawn directions against their lobe: histograms of θ and φ beside the marginal
 * densities, and the χ² test against the pdf.
 */
import { HALF_PI, TWO_PI, sphericalPhi, sphericalTheta } from '../../core/sampling';
import { hemisphereChi2, type HemisphereChi2Result } from '../../core/verify';
import type { Lobe } from './lobe';

/** A histogram normalized as a density (counts/(N·Δ)), with bin centres, beside the model density. */
export interface DensityHistogram {
  centers: Float64Array;
  density: Float64Array;
  /** Model density evaluated on a fine grid (for the curve). */
  curveX: Float64Array;
  curveY: Float64Array;
  width: number;
}

/** Histograms of θ over [0, π/2] and of φ over [0, 2π) against the lobe's marginals. */
export function marginalHistograms(
  lobe: Lobe,
  dirs: Float64Array,
  n: number,
  bins = 36,
): { theta: DensityHistogram; phi: DensityHistogram } {
  const ct = new Float64Array(bins);
  const cp = new Float64Array(bins);
  const wt = HALF_PI / bins;
  const wp = TWO_PI / bins;
  for (let i = 0; i < n; i++) {
    const x = dirs[3 * i];
    const y = dirs[3 * i + 1];
    const z = dirs[3 * i + 2];
    const t = sphericalTheta(x, y, z);
    const p = sphericalPhi(x, y);
    if (t >= 0 && t <= HALF_PI) ct[Math.min(bins - 1, Math.floor(t / wt))]++;
    if (p >= 0 && p < TWO_PI) cp[Math.min(bins - 1, Math.floor(p / wp))]++;
  }
  const make = (
    counts: Float64Array,
    w: number,
    lo: number,
    hi: number,
    f: (x: number) => number,
  ): DensityHistogram => {
    const centers = new Float64Array(bins);
    const density = new Float64Array(bins);
    for (let b = 0; b < bins; b++) {
      centers[b] = lo + (b + 0.5) * w;
      density[b] = n > 0 ? counts[b] / (n * w) : 0;
    }
    const m = 200;
    const curveX = new Float64Array(m + 1);
    const curveY = new Float64Array(m + 1);
    for (let j = 0; j <= m; j++) {
      const x = lo + ((hi - lo) * j) / m;
      curveX[j] = x;
      const xe = j === m ? hi * (1 - 1e-12) : x; // the half-open support of φ
      curveY[j] = f(xe);
    }
    return { centers, density, curveX, curveY, width: w };
  };
  return { theta: make(ct, wt, 0, HALF_PI, lobe.thetaPdf), phi: make(cp, wp, 0, TWO_PI, lobe.phiPdf) };
}

/** χ² test of the drawn directions against the lobe's pdf (core/verify, as in the unit tests). */
export function chi2OfDirections(lobe: Lobe, dirs: Float64Array, n: number): HemisphereChi2Result {
  const custom = lobe.id === 'custom';
  // bins of the typed lobe align with its 64 × 128 table (8 × 8 cells per bin), so the quadrature
  // of a piecewise-constant pdf stays cheap and exact
  return hemisphereChi2(
    dirs,
    n,
    lobe.pdf,
    custom ? { cosThetaBins: 8, phiBins: 16 } : { cosThetaBins: 10, phiBins: 20 },
  );
}
