/**
 * Tabulated (piecewise-constant) 2D distribution on a rectangle: a marginal distribution over
 * rows (v) and a conditional distribution within each row (u).
 * Source: pbrt-v4 `PiecewiseConstant2D` (util/sampling.h, §A.4.2 "Piecewise-Constant 2D
 * Distributions"); Pharr, Jakob & Humphreys, PBR 4th ed.
 */
import { DensityError, PiecewiseConstant1D, validateDensity } from './piecewise1D';

/** Rectangle [u0, u1] × [v0, v1] on which a 2D table is defined. */
export interface Domain2D {
  u0: number;
  u1: number;
  v0: number;
  v1: number;
}

/**
 * Density on the rectangle proportional to the table f, stored row-major: f[iv·nu + iu] is the value
 * on cell [u0 + iu·Δu, …) × [v0 + iv·Δv, …). Measure: per unit area in (u, v), so
 * ∫∫ pdf(u, v) du dv = 1; `integral` = Σ f·Δu·Δv is the inverse normalization constant.
 * Sampling picks a row from the marginal p(v) = ∫ f(u, v) du / integral, then u from that row's
 * conditional p(u | v) = f(u, v) / ∫ f(u', v) du'.
 */
export class PiecewiseConstant2D {
  readonly nu: number;
  readonly nv: number;
  readonly domain: Readonly<Domain2D>;
  /** Marginal distribution over rows v (its values are the row integrals ∫ f du). */
  readonly marginal: PiecewiseConstant1D;
  /** ∫∫ f du dv over the domain. */
  readonly integral: number;
  private readonly rows: PiecewiseConstant1D[];

  /**
   * @param f nu·nv values ≥ 0, finite, not all zero (throws {@link DensityError} otherwise)
   * @param nu columns (u), nv rows (v); positive integers with f.length = nu·nv (RangeError otherwise)
   * @param domain the rectangle, u0 < u1 and v0 < v1
   */
  constructor(
    f: ArrayLike<number>,
    nu: number,
    nv: number,
    domain: Domain2D = { u0: 0, u1: 1, v0: 0, v1: 1 },
  ) {
    if (!(Number.isInteger(nu) && Number.isInteger(nv) && nu >= 1 && nv >= 1 && f.length === nu * nv)) {
      throw new RangeError(`a ${nu}×${nv} table needs ${nu * nv} values, got ${f.length}`);
    }
    const check = validateDensity(f);
    if (!check.ok) throw new DensityError(check);
    this.nu = nu;
    this.nv = nv;
    this.domain = { ...domain };
    this.rows = [];
    // rows are built from f / max(f) so that row integrals cannot overflow or underflow
    let maxF = 0;
    for (let i = 0; i < f.length; i++) if (f[i] > maxF) maxF = f[i];
    const rowIntegrals = new Float64Array(nv);
    const row = new Float64Array(nu);
    for (let v = 0; v < nv; v++) {
      for (let u = 0; u < nu; u++) row[u] = f[v * nu + u] / maxF;
      const r = new PiecewiseConstant1D(row, domain.u0, domain.u1, { allowZero: true });
      this.rows.push(r);
      rowIntegrals[v] = r.integral;
    }
    this.marginal = new PiecewiseConstant1D(rowIntegrals, domain.v0, domain.v1);
    this.integral = maxF * this.marginal.integral;
  }

  /**
   * Conditional distribution p(u | v) of row i (clamped to [0, nv − 1]). Its `func` holds the row
   * divided by the table's maximum (its pdf is the true conditional density).
   */
  conditional(i: number): PiecewiseConstant1D {
    return this.rows[Math.max(0, Math.min(this.nv - 1, Math.floor(i)))];
  }

  /**
   * Sample (u, v) from (ξ1, ξ2) ∈ [0, 1)²: ξ2 picks v from the marginal, ξ1 picks u within that row.
   * Returns the joint pdf per unit area. Source: pbrt-v4 `PiecewiseConstant2D::Sample`.
   */
  sample(u1: number, u2: number): { u: number; v: number; pdf: number } {
    const m = this.marginal.sample(u2);
    const c = this.rows[m.offset].sample(u1);
    return { u: c.x, v: m.x, pdf: m.pdf * c.pdf };
  }

  /** Density per unit area at (u, v): f(cell)/integral inside the domain, 0 outside. */
  pdf(u: number, v: number): number {
    const d = this.domain;
    if (!(u >= d.u0 && u <= d.u1 && v >= d.v0 && v <= d.v1)) return 0;
    const iv = this.marginal.offsetOf(v);
    return this.marginal.pdfs[iv] * this.rows[iv].pdf(u);
  }

  /**
   * Inverse of {@link sample}: (ξ1, ξ2) ∈ [0, 1]² mapping to (u, v) — the conditional CDF in u
   * and the marginal CDF in v. Points outside the domain are clamped onto it.
   * Source: pbrt-v4 `PiecewiseConstant2D::Invert`.
   */
  invert(u: number, v: number): { u1: number; u2: number } {
    const u2 = this.marginal.invert(v);
    const iv = this.marginal.offsetOf(Math.min(Math.max(v, this.domain.v0), this.domain.v1));
    return { u1: this.rows[iv].invert(u), u2 };
  }
}
