/** Variances of one term of each Q2 estimator, by quadrature (warnings for infinite or huge variance). */
import { HALF_PI, TWO_PI } from '../../core/sampling';
import { adaptiveIntegrate2D } from '../../core/verify';
import type { Lobe } from './lobe';
import type { Integrand } from './integral';

/** Second moments and variances of one term of each Q2 estimator, by quadrature. */
export interface VarianceCheck {
  /** Var[2π f(X)], X uniform. */
  uniformVar: number;
  /** Var[f(X)/p(X)], X ~ p (over the region p > 0); Infinity when ∫ f²/p dω diverges. */
  importanceVar: number;
  /** true when ∫ f²/p dω diverges (the importance estimator has infinite variance). */
  infinite: boolean;
  /** importanceVar / uniformVar (Infinity when infinite; NaN when both are 0). */
  ratio: number;
}

/**
 * Var of the terms of both estimators: Var_u = 2π ∫ f² dω − I², Var_p = ∫ f²/p dω − I². The
 * importance second moment is integrated over μ = cos θ (dω = dμ dφ) in decades towards the
 * horizon μ → 0 and towards the pole μ → 1, where p may vanish; when the last decades stop
 * shrinking (each contributes at least 0.9 of the one before, as for ∫ dμ/μ), the integral
 * diverges and the variance is infinite.
 */
export function varianceCheck(lobe: Lobe, f: Integrand, exact: number): VarianceCheck {
  const opts = { relTol: 1e-8, maxDepth: 5, maxEvals: 60000 };
  const g = (mu: number, phi: number) => {
    const theta = Math.acos(Math.min(1, Math.max(0, mu)));
    const fv = f(theta, phi);
    if (fv === 0) return 0;
    const st = Math.sqrt(Math.max(0, 1 - mu * mu));
    const p = lobe.pdf(st * Math.cos(phi), st * Math.sin(phi), mu);
    return p > 0 && Number.isFinite(p) ? (fv * fv) / p : 0;
  };
  const f2 = adaptiveIntegrate2D((t, p) => f(t, p) ** 2 * Math.sin(t), 0, HALF_PI, 0, TWO_PI, opts);
  const uniformVar = Math.max(0, TWO_PI * f2 - exact * exact);
  const DEC = 12;
  // decades near the horizon: [10^-(j+1), 10^-j] for j = 1…DEC, and the same towards the pole (1 − μ)
  const horizon: number[] = [];
  const pole: number[] = [];
  for (let j = 1; j <= DEC; j++) {
    horizon.push(adaptiveIntegrate2D(g, 10 ** -(j + 1), 10 ** -j, 0, TWO_PI, opts));
    pole.push(adaptiveIntegrate2D(g, 1 - 10 ** -j, 1 - 10 ** -(j + 1), 0, TWO_PI, opts));
  }
  const middle = adaptiveIntegrate2D(g, 0.1, 0.9, 0, TWO_PI, opts);
  const sum = (a: number[]) => a.reduce((x, y) => x + y, 0);
  const m2 = middle + sum(horizon) + sum(pole);
  const diverges = (a: number[]) => {
    const last = a[a.length - 1];
    const prev = a[a.length - 2];
    return !Number.isFinite(last) || (last > 1e-9 * Math.max(1e-300, Math.abs(m2)) && last >= 0.9 * prev);
  };
  const infinite = !Number.isFinite(m2) || diverges(horizon) || diverges(pole);
  const importanceVar = infinite ? Infinity : Math.max(0, m2 - exact * exact);
  const ratio = infinite
    ? Infinity
    : uniformVar > 0
      ? importanceVar / uniformVar
      : importanceVar > 0
        ? Infinity
        : NaN;
  return { uniformVar, importanceVar, infinite, ratio };
}
