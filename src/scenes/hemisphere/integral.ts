/**
 * ∫ f dω over the upper hemisphere of a typed integrand f(θ, φ), with a verdict when it has no
 * value (f not finite somewhere, a divergent or unresolved integral).
 */
import { HALF_PI, TWO_PI } from '../../core/sampling';
import { adaptiveIntegrate2D } from '../../core/verify';

/** An integrand of (θ, φ) (compiled user expression). */
export type Integrand = (theta: number, phi: number) => number;

/**
 * ∫ f dω over the upper hemisphere = ∫₀^{2π} ∫₀^{π/2} f(θ, φ) sin θ dθ dφ, by adaptive
 * Gauss–Legendre quadrature (core/verify). NaN when f is not finite somewhere it is evaluated.
 */
export function exactIntegral(f: Integrand): number {
  return checkedIntegral(f).value;
}

/** ∫ f dω, or NaN with the reason it has no value. */
export interface CheckedIntegral {
  value: number;
  /** Why there is no value (f not finite somewhere, the quadrature does not converge); null if fine. */
  problem: string | null;
  /** The quadrature's own error estimate (summed over its final cells). */
  error: number;
  /** Set when the value is usable but less accurate than the readout's digits. */
  note?: string;
}

/** Relative error above which the quadrature's value is not trusted (a divergent or unresolved integral). */
const UNRESOLVED_REL = 1e-6;
/** An unresolved error must shrink at least this much per level of refinement to count as converging. */
const SHRINK_RATIO = 0.75;
/** Relative error above which the value is not shown at all. */
const UNTRUSTED_REL = 1e-2;

function deg(x: number): string {
  return `${(x * (180 / Math.PI)).toFixed(1)}°`;
}

/** A point (θ, φ) of a 64 × 128 grid (cell centres and edges) where f is not finite, or null. */
export function findNonFinite(f: Integrand): { theta: number; phi: number } | null {
  for (let i = 0; i <= 128; i++) {
    const t = (i / 128) * HALF_PI;
    for (let j = 0; j < 256; j++) {
      const p = (j / 256) * TWO_PI;
      if (!Number.isFinite(f(t, p))) return { theta: t, phi: p };
    }
  }
  return null;
}

/**
 * ∫ f dω with a verdict, like the monte-carlo scene's: NaN and a reason when f is not finite
 * somewhere on the hemisphere, or when the adaptive quadrature's error does not shrink (at its
 * depth limit a divergent integral, e.g. tan θ or 1/cos θ at the horizon, θ⁻² at the pole, or
 * 1/(θ − 0.5) inside, keeps an error of the order of the integral itself).
 */
export function checkedIntegral(f: Integrand): CheckedIntegral {
  const report = { error: NaN, resolved: false };
  const v = adaptiveIntegrate2D((t, p) => f(t, p) * Math.sin(t), 0, HALF_PI, 0, TWO_PI, {
    relTol: 1e-12,
    maxDepth: 6,
    report,
  });
  if (!Number.isFinite(v)) {
    const at = findNonFinite(f);
    return {
      value: NaN,
      error: Infinity,
      problem: at
        ? `f is not finite (NaN or ±∞) at θ = ${deg(at.theta)}, φ = ${deg(at.phi)}, so ∫ f dω has no value`
        : 'f is not finite (NaN or ±∞) somewhere on the hemisphere, so ∫ f dω has no value',
    };
  }
  if (!(report.error <= UNRESOLVED_REL * Math.abs(v) + 1e-12)) {
    // Not resolved to the tolerance: an integrable singularity's error still shrinks with depth
    // (by 2^-1/2 per bisection for 1/√cos θ), a divergent one's does not (ln 2 · coefficient per
    // bisection for a 1/x blow-up). Compare one level shallower.
    const coarse = { error: NaN, resolved: false };
    adaptiveIntegrate2D((t, p) => f(t, p) * Math.sin(t), 0, HALF_PI, 0, TWO_PI, {
      relTol: 1e-12,
      maxDepth: 5,
      report: coarse,
    });
    if (!(report.error < SHRINK_RATIO * coarse.error) || !(report.error <= UNTRUSTED_REL * Math.abs(v)))
      return {
        value: NaN,
        error: report.error,
        problem: `the quadrature does not converge (its error estimate stays at ${report.error.toPrecision(2)} while refining): ∫ f dω diverges, or f has a singularity too strong to resolve`,
      };
    return {
      value: v,
      error: report.error,
      problem: null,
      note: `accurate to about ±${report.error.toPrecision(2)} only (f has a singularity the quadrature resolves slowly)`,
    };
  }
  return { value: v, error: report.error, problem: null };
}
