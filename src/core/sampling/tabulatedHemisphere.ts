/**
 * A density typed by the user, p(θ, φ) per unit solid angle on the upper hemisphere, made
 * sampleable by tabulation: the hemisphere is cut into cells of equal solid angle, equal steps in
 * z = cos θ ∈ [0, 1] (rows) and in φ ∈ [0, 2π) (columns) — since dω = dz dφ, a table over (φ, z)
 * with {@link PiecewiseConstant2D} is directly a density per steradian. Rows (z) are the marginal,
 * φ within a row the conditional: p(ω) = p(z) · p(φ | z), the non-separable analogue of the exam's
 * p(θ) p(φ).
 *
 * Checks, each with a plain-language message (never NaN numbers downstream):
 *  - negative anywhere on the table or the probes → 'negative';
 *  - NaN / ±∞ (or not a number) → 'nonfinite';
 *  - zero everywhere → 'zero';
 *  - not integrable: the mass of shrinking rings/strips at the pole (θ → 0), the horizon
 *    (θ → π/2) and the seam (φ → 0, φ → 2π) must vanish; a density like cos θ / sin²θ (the key's
 *    upside-down Jacobian written per solid angle) or 1/cos θ keeps a non-vanishing mass there and
 *    is reported as 'divergent';
 *  - a table whose integral changes by more than 5 % when the grid is refined gives a warning
 *    (a sharp feature the table cannot resolve, or a singularity inside the domain).
 *
 * Source: pbrt-v4 §A.4.2 (PiecewiseConstant2D) and §2.4.2 (sampling a tabulated environment map
 * by marginal and conditional); Gauss–Legendre probes after Numerical Recipes §4.6.
 */
import { formatRounded } from '../format';
import type { Failure } from '../failure';
import { gaussLegendre } from '../verify/quadrature';
import { DensityError, PiecewiseConstant1D } from './piecewise1D';
import { PiecewiseConstant2D } from './piecewise2D';
import {
  HALF_PI,
  TWO_PI,
  TWO_PI_BELOW,
  clampUnit,
  sphericalPhi,
  writeSphericalDirection,
  type VecOut,
} from './sphericalCoords';

/** A density over solid angle in (θ, φ); may return anything (validated). */
export type ThetaPhiDensity = (theta: number, phi: number) => number;

/** Options of {@link tabulateHemisphereDensity}. */
export interface TabulateOptions {
  /** Rows in z = cos θ (default 64). */
  cosThetaBins?: number;
  /** Columns in φ (default 128). */
  phiBins?: number;
}

/** Why a typed density was rejected. */
export interface TabulateFailure extends Failure<'negative' | 'nonfinite' | 'zero' | 'divergent' | 'error'> {
  /** Where the problem was found (θ, φ in radians), when it has a place. */
  readonly at?: { theta: number; phi: number };
}

/** Result of {@link tabulateHemisphereDensity}. */
export type TabulateResult = { ok: true; lobe: TabulatedHemisphere; warning?: string } | TabulateFailure;

const { x: GL4_X, w: GL4_W } = gaussLegendre(4);

class Invalid extends Error {
  constructor(readonly failure: TabulateFailure) {
    super(failure.message);
  }
}

/** Evaluate p at (θ, φ), throwing {@link Invalid} for negative or non-finite values. */
function evalChecked(p: ThetaPhiDensity, theta: number, phi: number): number {
  let v: unknown;
  try {
    v = p(theta, phi);
  } catch (e) {
    throw new Invalid({
      ok: false,
      kind: 'error',
      message: `evaluating the density failed at θ = ${formatRounded(theta)}, φ = ${formatRounded(phi)}: ${e instanceof Error ? e.message : String(e)}`,
      at: { theta, phi },
    });
  }
  if (typeof v !== 'number' || !Number.isFinite(v)) {
    throw new Invalid({
      ok: false,
      kind: 'nonfinite',
      message: `the density is not a finite number at θ = ${formatRounded(theta)}, φ = ${formatRounded(phi)} (${typeof v !== 'number' ? `it gives a ${typeof v}` : Number.isNaN(v) ? 'it is undefined there' : 'it is infinite there'}); a pdf must be finite to be normalized`,
      at: { theta, phi },
    });
  }
  if (v < 0) {
    throw new Invalid({
      ok: false,
      kind: 'negative',
      message: `the density is negative (${formatRounded(v)}) at θ = ${formatRounded(theta)}, φ = ${formatRounded(phi)}; a pdf must be ≥ 0 everywhere`,
      at: { theta, phi },
    });
  }
  return v;
}

/** ∫∫ p dω over θ ∈ [t0, t1], φ ∈ [p0, p1] by 4×4 Gauss–Legendre per panel (np panels in φ). */
function massThetaPhi(p: ThetaPhiDensity, t0: number, t1: number, p0: number, p1: number, np = 8): number {
  let s = 0;
  const ht = (t1 - t0) / 2;
  const hp = (p1 - p0) / np / 2;
  for (let k = 0; k < np; k++) {
    const pc = p0 + (2 * k + 1) * hp;
    for (let a = 0; a < 4; a++) {
      const th = t0 + ht * (1 + GL4_X[a]);
      const st = Math.sin(th);
      for (let b = 0; b < 4; b++) {
        const ph = pc + hp * GL4_X[b];
        s += GL4_W[a] * GL4_W[b] * evalChecked(p, th, ph) * st;
      }
    }
  }
  return s * ht * hp;
}

/**
 * Divergence probes: masses of geometrically shrinking regions at the four places a typed density
 * typically blows up. For an integrable density the mass of the region at scale 2⁻⁴⁰ is negligible
 * (it is ~2⁻⁴⁰ or smaller for anything bounded or mildly singular); a non-vanishing mass there means
 * the integral diverges (e.g. ∫ dθ/θ). Returns a failure or null.
 */
function probeDivergence(p: ThetaPhiDensity, total: number): TabulateFailure | null {
  const H = HALF_PI;
  const scales = [2 ** -10, 2 ** -20, 2 ** -30, 2 ** -40];
  const probes: { name: string; region: (e: number) => [number, number, number, number]; explain: string }[] =
    [
      { name: 'the pole θ → 0', region: (e) => [e / 2, e, 0, TWO_PI], explain: '∫ p sin θ dθ near θ = 0' },
      {
        name: 'the horizon θ → π/2',
        region: (e) => [H - e, H - e / 2, 0, TWO_PI],
        explain: '∫ p sin θ dθ near θ = π/2',
      },
      { name: 'φ → 0', region: (e) => [0, H, e / 2, e], explain: '∫ p dφ near φ = 0' },
      { name: 'φ → 2π', region: (e) => [0, H, TWO_PI - e, TWO_PI - e / 2], explain: '∫ p dφ near φ = 2π' },
    ];
  for (const pr of probes) {
    const masses = scales.map((e) => {
      const [t0, t1, p0, p1] = pr.region(e);
      return massThetaPhi(p, t0, t1, p0, p1);
    });
    const last = masses[masses.length - 1];
    // a dyadic shell at scale 2⁻⁴⁰ holding more than 1e-6 of the total (or more than the shell at
    // 2⁻¹⁰ shrunk by 2⁻¹⁰) does not vanish: the integral diverges logarithmically or worse
    // (Only the shrinking decides when there is mass at 2⁻¹⁰: a sharp lobe such as cos¹⁰⁰⁰⁰θ, whose
    // peak the table misses, has a tiny table total but a mass at the pole that shrinks like e².)
    if (
      !Number.isFinite(last) ||
      (masses[0] === 0 && last > 1e-6 * total) ||
      (masses[0] > 0 && last > masses[0] * 2 ** -10 && last > 1e-9 * total)
    ) {
      const [t0, , p0] = pr.region(scales[scales.length - 1]);
      return {
        ok: false,
        kind: 'divergent',
        message: `the density is not integrable at ${pr.name}: ${pr.explain} does not shrink as the region shrinks (mass ${formatRounded(masses[0])}, ${formatRounded(masses[1])}, ${formatRounded(masses[2])}, ${formatRounded(last)} in regions of size 2⁻¹⁰ … 2⁻⁴⁰), so ∫ p dω = ∞ and no k can normalize it`,
        at: { theta: t0, phi: p0 },
      };
    }
  }
  return null;
}

function table(p: ThetaPhiDensity, nz: number, nphi: number): Float64Array {
  const f = new Float64Array(nz * nphi);
  for (let iz = 0; iz < nz; iz++) {
    const z = (iz + 0.5) / nz;
    const theta = Math.acos(z);
    for (let ip = 0; ip < nphi; ip++) f[iz * nphi + ip] = evalChecked(p, theta, ((ip + 0.5) / nphi) * TWO_PI);
  }
  return f;
}

/**
 * Tabulate a typed density over solid angle and build its sampler, or explain why it cannot be a
 * pdf. Domain: p any function of (θ, φ) (θ ∈ [0, π/2] polar from +z, φ ∈ [0, 2π)); it need not be
 * normalized (k = 1/∫ p dω is computed). Cells are of equal solid angle (equal steps in cos θ and φ);
 * values are taken at cell centres (midpoint rule). Measure: solid angle.
 */
export function tabulateHemisphereDensity(p: ThetaPhiDensity, opts: TabulateOptions = {}): TabulateResult {
  const nz = Math.max(2, Math.floor(opts.cosThetaBins ?? 64));
  const nphi = Math.max(2, Math.floor(opts.phiBins ?? 128));
  try {
    const f = table(p, nz, nphi);
    let any = false;
    for (let i = 0; i < f.length; i++) if (f[i] > 0) any = true;
    if (!any)
      return {
        ok: false,
        kind: 'zero',
        message: 'the density is zero everywhere on the hemisphere, so it cannot be normalized',
      };
    const lobe = new TabulatedHemisphere(f, nz, nphi);
    const div = probeDivergence(p, lobe.integral);
    if (div) return div;
    // refinement check: the integral on a grid twice as fine in each direction
    const fine = table(p, 2 * nz, 2 * nphi);
    let fineSum = 0;
    for (let i = 0; i < fine.length; i++) fineSum += fine[i];
    const fineIntegral = (fineSum * TWO_PI) / (4 * nz * nphi);
    const rel = Math.abs(fineIntegral - lobe.integral) / lobe.integral;
    const warning =
      rel > 0.05
        ? `the tabulated integral changes by ${formatRounded(100 * rel)} % when the ${nz}×${nphi} grid is refined (${formatRounded(lobe.integral)} → ${formatRounded(fineIntegral)}): the density has features finer than the table can resolve (a sharp peak, or a singularity inside), so the sampled lobe only approximates it`
        : undefined;
    return warning ? { ok: true, lobe, warning } : { ok: true, lobe };
  } catch (e) {
    if (e instanceof Invalid) return e.failure;
    if (e instanceof DensityError) return { ok: false, kind: e.reason, message: e.message };
    return { ok: false, kind: 'error', message: e instanceof Error ? e.message : String(e) };
  }
}

/**
 * Sampler, pdf and inverse of a tabulated density over the upper hemisphere (see the module
 * comment). ξ₁ picks z = cos θ from the marginal (ξ₁ = 0 at the horizon), ξ₂ picks φ from the
 * conditional of that row. The pdf is per steradian and exactly the density that is sampled (the
 * piecewise-constant table / its integral), so the χ² test checks the sampler against it.
 */
export class TabulatedHemisphere {
  /** The table as a 2D distribution: u = φ ∈ [0, 2π], v = z = cos θ ∈ [0, 1]. */
  readonly dist: PiecewiseConstant2D;
  /** ∫ p dω of the table (midpoint rule): the normalization is k = 1/integral. */
  readonly integral: number;
  /** Rows in z and columns in φ. */
  readonly nz: number;
  readonly nphi: number;
  /** Marginal of φ, per unit φ, one value per column. */
  readonly phiMarginal: Float64Array;

  /** @param f nz·nphi values (row-major, z rows from the horizon up), ≥ 0, finite, not all zero. */
  constructor(f: ArrayLike<number>, nz: number, nphi: number) {
    this.dist = new PiecewiseConstant2D(f, nphi, nz, { u0: 0, u1: TWO_PI, v0: 0, v1: 1 });
    this.integral = this.dist.integral;
    this.nz = nz;
    this.nphi = nphi;
    const pm = new Float64Array(nphi);
    let total = 0;
    for (let iz = 0; iz < nz; iz++) for (let ip = 0; ip < nphi; ip++) total += f[iz * nphi + ip];
    for (let iz = 0; iz < nz; iz++) for (let ip = 0; ip < nphi; ip++) pm[ip] = pm[ip] + f[iz * nphi + ip];
    for (let ip = 0; ip < nphi; ip++) pm[ip] = (pm[ip] / total) * (nphi / TWO_PI);
    this.phiMarginal = pm;
  }

  /** Normalization constant k = 1/∫ p dω of the typed (unnormalized) density. */
  get k(): number {
    return 1 / this.integral;
  }

  /** Sample one direction from (ξ₁, ξ₂) ∈ [0, 1)²; writes the unit vector to out[o..o+2]. */
  sample(u1: number, u2: number, out: VecOut, o = 0): VecOut {
    const s = this.dist.sample(u2, u1); // v (z) from the marginal with ξ₁, u (φ) with ξ₂
    const z = s.v;
    return writeSphericalDirection(Math.sqrt(Math.max(0, (1 - z) * (1 + z))), z, s.u, out, o);
  }

  /**
   * Batched {@link sample}: u[2i], u[2i+1] → out[3i..3i+2] for i ∈ [start, n); no allocation.
   * A hand-inlined twin of {@link sample} (which goes through `PiecewiseConstant2D.sample` and
   * allocates its result object per call); kept because bench/sampling.bench.ts measures it faster.
   */
  sampleBatch(u: Float64Array, out: Float64Array, n: number, start = 0): Float64Array {
    const mc = this.dist.marginal.cdf;
    const nz = this.nz;
    const nphi = this.nphi;
    for (let i = start; i < n; i++) {
      const a = u[2 * i];
      const lo = cdfSegment(mc, nz, a);
      const w = mc[lo + 1] - mc[lo];
      let du = w > 0 ? (a - mc[lo]) / w : 0;
      if (du > 1) du = 1;
      const z = Math.min(1, (lo + du) / nz);
      const rc = this.dist.conditional(lo).cdf;
      const b = u[2 * i + 1];
      const lo2 = cdfSegment(rc, nphi, b);
      const w2 = rc[lo2 + 1] - rc[lo2];
      let dv = w2 > 0 ? (b - rc[lo2]) / w2 : 0;
      if (dv > 1) dv = 1;
      let phi = ((lo2 + dv) / nphi) * TWO_PI;
      if (phi >= TWO_PI) phi = TWO_PI_BELOW;
      const r = Math.sqrt(Math.max(0, (1 - z) * (1 + z)));
      out[3 * i] = r * Math.cos(phi);
      out[3 * i + 1] = r * Math.sin(phi);
      out[3 * i + 2] = z;
    }
    return out;
  }

  /** Density per steradian at the unit direction (x, y, z): 0 for z < 0 or NaN. */
  pdf(x: number, y: number, z: number): number {
    if (!(z >= 0 && z <= 1)) return 0;
    const phi = sphericalPhi(x, y);
    if (!Number.isFinite(phi)) return 0;
    return this.dist.pdf(phi, z);
  }

  /** Inverse of {@link sample}: (ξ₁, ξ₂) for the direction (x, y, z), z ≥ 0. */
  invert(x: number, y: number, z: number): [number, number] {
    const r = this.dist.invert(sphericalPhi(x, y), z);
    return [clampUnit(r.u2), clampUnit(r.u1)];
  }

  /** Marginal density of θ per unit θ: p_z(cos θ) · sin θ on [0, π/2], 0 elsewhere. */
  thetaPdf(theta: number): number {
    if (!(theta >= 0 && theta <= Math.PI / 2)) return 0;
    return this.dist.marginal.pdf(Math.cos(theta)) * Math.sin(theta);
  }

  /** Marginal density of φ per unit φ on [0, 2π), 0 elsewhere. */
  phiPdf(phi: number): number {
    if (!(phi >= 0 && phi < TWO_PI)) return 0;
    return this.phiMarginal[Math.min(this.nphi - 1, Math.floor((phi / TWO_PI) * this.nphi))];
  }

  /** The marginal over rows (z), for plots. */
  get zMarginal(): PiecewiseConstant1D {
    return this.dist.marginal;
  }
}

/** The segment i ∈ [0, size) of a CDF table (size + 1 entries, non-decreasing) with cdf[i] ≤ a < cdf[i+1]. */
function cdfSegment(cdf: Float64Array, size: number, a: number): number {
  let lo = 0;
  let hi = size;
  while (hi - lo > 1) {
    const mid = (lo + hi) >>> 1;
    if (cdf[mid] <= a) lo = mid;
    else hi = mid;
  }
  return lo;
}
