import { TWO_PI } from '../sampling/sphericalCoords';
import { chi2Test, type Chi2Result } from './chi2';
import { adaptiveIntegrate2D, type AdaptiveOptions } from './quadrature';

/** Options of {@link hemisphereChi2}. */
export interface HemisphereChi2Options {
  /** Number of bins in cos θ over [0, 1] (or [−1, 1] with `sphere`); default 10. */
  cosThetaBins?: number;
  /** Number of bins in φ over [0, 2π); default 20. */
  phiBins?: number;
  /** Overall significance (default 0.01). */
  alpha?: number;
  /** Pooling threshold for expected counts (default 5). */
  minExpected?: number;
  /** Number of tests run together, for the Šidák correction (default 1). */
  tests?: number;
  /** Bin the whole sphere (cos θ ∈ [−1, 1]) instead of the upper hemisphere; default false. */
  sphere?: boolean;
  /**
   * Total pdf evaluations allowed for the expected counts (default 4 000 000, shared evenly by the
   * bins): bounds the time even for a discontinuous or very peaked pdf (about 0.1–0.3 s).
   */
  maxEvals?: number;
}

/** Result of {@link hemisphereChi2}: the χ² result plus the histograms (row-major, cos θ rows). */
export interface HemisphereChi2Result extends Chi2Result {
  /** Observed counts, index = iCosTheta · phiBins + iPhi. */
  observed: Float64Array;
  /** Expected counts N ∫∫_bin p(ω) d(cos θ) dφ, same layout. */
  expected: Float64Array;
  cosThetaBins: number;
  phiBins: number;
  /** Samples that were not finite or fell outside the binned domain (they fail the test). */
  outside: number;
}

/**
 * χ² test of directions against a pdf on the hemisphere around +z (z-up, θ from +z, φ from +x
 * towards +y). Bins are equal in (cos θ, φ), i.e. of equal solid angle, since dω = d(cos θ) dφ.
 * Expected counts integrate the pdf over each bin by adaptive Gauss–Legendre quadrature in
 * (cos θ, φ), so any pdf can be tested, including ones with kinks or tabulated steps.
 *
 * Domain: `dirs` holds `count` unit vectors, xyz interleaved. `pdf` is per unit solid angle (sr⁻¹)
 * and must be 0 outside its support. Directions with z < 0 (with `sphere` false), or non-finite
 * components, count as impossible samples and fail the test.
 * Source: Nori `warptest.cpp` and Mitsuba 3 `chi2.py` (SphericalDomain), Jakob's χ² warp tests.
 */
export function hemisphereChi2(
  dirs: Float64Array,
  count: number,
  pdf: (x: number, y: number, z: number) => number,
  opts: HemisphereChi2Options = {},
): HemisphereChi2Result {
  const nc = Math.max(1, Math.floor(opts.cosThetaBins ?? 10));
  const np = Math.max(1, Math.floor(opts.phiBins ?? 20));
  const zMin = opts.sphere ? -1 : 0;
  const observed = new Float64Array(nc * np);
  const expected = new Float64Array(nc * np);
  const n = Math.max(0, Math.min(Math.floor(count), Math.floor(dirs.length / 3)));
  let outside = 0;
  const cScale = nc / (1 - zMin);
  const pScale = np / TWO_PI;
  for (let i = 0; i < n; i++) {
    const x = dirs[3 * i];
    const y = dirs[3 * i + 1];
    const z = dirs[3 * i + 2];
    if (!(Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z)) || z < zMin) {
      outside++;
      continue;
    }
    let ic = Math.floor((z - zMin) * cScale);
    if (ic >= nc) ic = nc - 1;
    let phi = Math.atan2(y, x);
    if (phi < 0) phi += TWO_PI;
    let ip = Math.floor(phi * pScale);
    if (ip >= np) ip = np - 1;
    if (ip < 0) ip = 0;
    observed[ic * np + ip]++;
  }
  const integrand = (c: number, phi: number): number => {
    const s = Math.sqrt(Math.max(0, 1 - c * c));
    return pdf(s * Math.cos(phi), s * Math.sin(phi), c);
  };
  const quad = quadratureOptions(opts.maxEvals, nc * np);
  for (let ic = 0; ic < nc; ic++) {
    const c0 = zMin + ((1 - zMin) * ic) / nc;
    const c1 = zMin + ((1 - zMin) * (ic + 1)) / nc;
    for (let ip = 0; ip < np; ip++) {
      const p0 = (TWO_PI * ip) / np;
      const p1 = (TWO_PI * (ip + 1)) / np;
      expected[ic * np + ip] = n * adaptiveIntegrate2D(integrand, c0, c1, p0, p1, quad);
    }
  }
  const res = withOutside(chi2Test(observed, expected, opts), outside);
  return { ...res, observed, expected, cosThetaBins: nc, phiBins: np, outside };
}

/** Options of {@link planarChi2}. */
export interface PlanarChi2Options {
  /** Bins along x (default 20). */
  xBins?: number;
  /** Total pdf evaluations allowed for the expected counts (default 4 000 000, shared by the bins). */
  maxEvals?: number;
  /** Bins along y (default 20). */
  yBins?: number;
  /** The binned rectangle (default the unit square). */
  domain?: { x0: number; x1: number; y0: number; y1: number };
  alpha?: number;
  minExpected?: number;
  tests?: number;
}

/** Result of {@link planarChi2}: the χ² result plus the histograms (row-major, y rows). */
export interface PlanarChi2Result extends Chi2Result {
  /** Observed counts, index = iy · xBins + ix. */
  observed: Float64Array;
  /** Expected counts N ∫∫_bin p(x, y) dx dy, same layout. */
  expected: Float64Array;
  xBins: number;
  yBins: number;
  /** Samples that were not finite or fell outside the domain (they fail the test). */
  outside: number;
}

/**
 * χ² test of 2D points against a density on a rectangle. Domain: `points` holds `count` points,
 * xy interleaved; `pdf` is per unit area of the plane and should integrate to 1 over `domain`.
 * Points outside [x0,x1)×[y0,y1) (or non-finite) fail the test. Expected counts by adaptive
 * Gauss–Legendre quadrature over each bin. Source: Mitsuba 3 `chi2.py` (PlanarDomain).
 */
export function planarChi2(
  points: Float64Array,
  count: number,
  pdf: (x: number, y: number) => number,
  opts: PlanarChi2Options = {},
): PlanarChi2Result {
  const nx = Math.max(1, Math.floor(opts.xBins ?? 20));
  const ny = Math.max(1, Math.floor(opts.yBins ?? 20));
  const { x0, x1, y0, y1 } = opts.domain ?? { x0: 0, x1: 1, y0: 0, y1: 1 };
  const observed = new Float64Array(nx * ny);
  const expected = new Float64Array(nx * ny);
  const n = Math.max(0, Math.min(Math.floor(count), Math.floor(points.length / 2)));
  const sx = nx / (x1 - x0);
  const sy = ny / (y1 - y0);
  let outside = 0;
  for (let i = 0; i < n; i++) {
    const x = points[2 * i];
    const y = points[2 * i + 1];
    if (!(x >= x0 && x <= x1 && y >= y0 && y <= y1)) {
      outside++;
      continue;
    }
    const ix = Math.min(nx - 1, Math.floor((x - x0) * sx));
    const iy = Math.min(ny - 1, Math.floor((y - y0) * sy));
    observed[iy * nx + ix]++;
  }
  const quad = quadratureOptions(opts.maxEvals, nx * ny);
  for (let iy = 0; iy < ny; iy++) {
    const b0 = y0 + ((y1 - y0) * iy) / ny;
    const b1 = y0 + ((y1 - y0) * (iy + 1)) / ny;
    for (let ix = 0; ix < nx; ix++) {
      const a0 = x0 + ((x1 - x0) * ix) / nx;
      const a1 = x0 + ((x1 - x0) * (ix + 1)) / nx;
      expected[iy * nx + ix] = n * adaptiveIntegrate2D(pdf, a0, a1, b0, b1, quad);
    }
  }
  const res = withOutside(chi2Test(observed, expected, opts), outside);
  return { ...res, observed, expected, xBins: nx, yBins: ny, outside };
}

/**
 * Per-bin quadrature settings: relative accuracy 1e-9 (far below the χ² test's resolution, which is
 * ~1/√(expected count)) and an equal share of the total evaluation budget.
 */
function quadratureOptions(maxEvals: number | undefined, bins: number): AdaptiveOptions {
  const total = maxEvals !== undefined && maxEvals > 0 ? maxEvals : 4_000_000;
  return { relTol: 1e-9, maxEvals: Math.max(500, Math.floor(total / bins)) };
}

function withOutside(res: Chi2Result, outside: number): Chi2Result {
  if (outside === 0) return res;
  return {
    ...res,
    pValue: 0,
    pass: false,
    note: `${outside} sample(s) fell outside the domain or were not finite`,
  };
}
