/**
 * Floating-point stability of the exam's inversion formulas (Q1(d)). The forms are equal in exact
 * arithmetic, not in doubles; this module evaluates each at chosen ξ and compares it with a
 * high-precision reference, for the scene's numerical-stability panel and for the tests.
 *
 *  θ(ξ₁): ½ arccos(1 − 2ξ₁)  — loses everything for tiny ξ₁ (1 − 2ξ₁ rounds to 1 once ξ₁ < 2⁻⁵⁴,
 *                               and keeps only ~half the digits above that), fine near ξ₁ → 1;
 *         arcsin √ξ₁         — accurate for tiny ξ₁, but arcsin is ill-conditioned at 1, so for ξ₁
 *                               near 1 the rounding of √ξ₁ is amplified;
 *         atan2(√ξ₁, √(1−ξ₁)) — the stable form (sin θ = √ξ₁, cos θ = √(1−ξ₁); see examLobe.ts).
 *  φ(ξ₂): ln((e^{2π} − 1) ξ₂ + 1) — relative precision lost for tiny ξ₂ (the +1 swamps c ξ₂);
 *         log1p(expm1(2π) ξ₂)     — accurate everywhere.
 *
 * The reference is computed with decimal.js (64 significant digits; mathjs' BigNumber is built on
 * it) on the exact double ξ, loaded lazily (`import('decimal.js')`) so the page only pays for it
 * when the panel is opened.
 * Source: Goldberg 1991, "What every computer scientist should know about floating-point
 * arithmetic" (log1p/expm1, cancellation); Higham, "Accuracy and Stability of Numerical
 * Algorithms", 2nd ed., ch. 1.
 */
import { EXAM_E2PI_M1 } from './examLobe';
import { TWO_PI } from './sphericalCoords';
import { ulp } from '../geometry/ulp';

/** ½ arccos(1 − 2ξ), the key's θ inversion. Domain ξ ∈ [0, 1]. */
export function thetaFromXiAcos(xi: number): number {
  return 0.5 * Math.acos(Math.min(1, Math.max(-1, 1 - 2 * xi)));
}

/** arcsin √ξ, the equivalent θ inversion. Domain ξ ∈ [0, 1]. */
export function thetaFromXiAsin(xi: number): number {
  return Math.asin(Math.min(1, Math.sqrt(Math.max(0, xi))));
}

/** atan2(√ξ, √(1 − ξ)): the stable θ inversion (sin θ = √ξ, cos θ = √(1 − ξ)). Domain ξ ∈ [0, 1]. */
export function thetaFromXiStable(xi: number): number {
  return Math.atan2(Math.sqrt(Math.max(0, xi)), Math.sqrt(Math.max(0, 1 - xi)));
}

/** ln((e^{2π} − 1) ξ + 1) with e^{2π} − 1 evaluated as written (exp(2π) − 1): the key's φ form. */
export function phiFromXiLog(xi: number): number {
  return Math.log((Math.exp(TWO_PI) - 1) * xi + 1);
}

/** log1p(expm1(2π) ξ): the stable φ form used by the sampler. Domain ξ ∈ [0, 1]. */
export function phiFromXiLog1p(xi: number): number {
  return Math.log1p(EXAM_E2PI_M1 * xi);
}

/** One named floating-point form of an inversion formula. */
export interface StabilityForm {
  id: string;
  /** LaTeX of the formula as the panel shows it. */
  tex: string;
  quantity: 'theta' | 'phi';
  fn: (xi: number) => number;
}

/** The forms the panel compares, θ first, then φ. */
export const STABILITY_FORMS: readonly StabilityForm[] = [
  { id: 'theta-acos', quantity: 'theta', tex: '\\tfrac12\\arccos(1-2\\xi_1)', fn: thetaFromXiAcos },
  { id: 'theta-asin', quantity: 'theta', tex: '\\arcsin\\sqrt{\\xi_1}', fn: thetaFromXiAsin },
  {
    id: 'theta-atan2',
    quantity: 'theta',
    tex: '\\operatorname{atan2}(\\sqrt{\\xi_1},\\sqrt{1-\\xi_1})',
    fn: thetaFromXiStable,
  },
  { id: 'phi-log', quantity: 'phi', tex: '\\ln\\big((e^{2\\pi}-1)\\xi_2+1\\big)', fn: phiFromXiLog },
  {
    id: 'phi-log1p',
    quantity: 'phi',
    tex: '\\operatorname{log1p}\\big(\\operatorname{expm1}(2\\pi)\\,\\xi_2\\big)',
    fn: phiFromXiLog1p,
  },
];

/** The ξ values the panel evaluates: tiny, moderate and near 1 (all exactly representable). */
export const STABILITY_XIS: readonly number[] = [
  1e-300,
  2 ** -53,
  1e-12,
  1e-6,
  0.5,
  1 - 1e-6,
  1 - 1e-12,
  1 - 2 ** -53,
];

export { ulp };

/** Error of one value against a reference: relative error and error in ulps of the reference. */
export interface ErrorMeasure {
  value: number;
  reference: number;
  relError: number;
  ulps: number;
}

/** Relative error |v − ref|/|ref| (absolute if ref = 0) and |v − ref|/ulp(ref). */
export function measureError(value: number, reference: number): ErrorMeasure {
  const d = Math.abs(value - reference);
  const relError = reference === 0 ? d : d / Math.abs(reference);
  return { value, reference, relError, ulps: d / ulp(reference) };
}

/** References for θ(ξ) = arcsin √ξ and φ(ξ) = ln(1 + (e^{2π} − 1) ξ) at each ξ, rounded to doubles. */
export interface StabilityReference {
  xi: number[];
  theta: number[];
  phi: number[];
}

/**
 * High-precision references in 64-digit decimal arithmetic (decimal.js, the library under mathjs'
 * BigNumber), on the exact binary value of each ξ. Async because decimal.js is imported lazily.
 * Domain: ξ ∈ [0, 1].
 */
export async function computeStabilityReference(xis: readonly number[]): Promise<StabilityReference> {
  const { default: Decimal } = await import('decimal.js');
  const D = Decimal.clone({ precision: 64 });
  const pi = D.acos(-1);
  const c = D.exp(pi.times(2)).minus(1);
  const tiny = new D('1e-10');
  const theta: number[] = [];
  const phi: number[] = [];
  for (const xi of xis) {
    const b = new D(exactDecimal(xi));
    theta.push(Number(b.sqrt().asin().toString()));
    // ln(1 + y): for tiny y, 1 + y would round at 64 digits, so use the series y − y²/2 + y³/3 − y⁴/4
    // (truncation error < y⁵ < 1e-50 relative to y for y < 1e-10)
    const y = c.times(b);
    const lg = y.lt(tiny)
      ? y.minus(y.pow(2).div(2)).plus(y.pow(3).div(3).minus(y.pow(4).div(4)))
      : y.plus(1).ln();
    phi.push(Number(lg.toString()));
  }
  return { xi: [...xis], theta, phi };
}

/**
 * The exact decimal expansion of a double (every binary fraction has a finite decimal one), so that
 * BigNumber receives precisely the value the double holds, not its shortest round-trip string.
 * Domain: finite x ≥ 0 (the ξ values used here).
 */
export function exactDecimal(x: number): string {
  if (x === 0) return '0';
  // x = mant · 2^exp with integer mant < 2^53
  let exp = 0;
  let mant = x;
  while (!Number.isInteger(mant)) {
    mant *= 2;
    exp--;
  }
  let big = BigInt(mant);
  if (exp >= 0) return (big << BigInt(exp)).toString();
  const k = -exp;
  // mant / 2^k = mant · 5^k / 10^k
  big *= 5n ** BigInt(k);
  const s = big.toString().padStart(k + 1, '0');
  const intPart = s.slice(0, s.length - k);
  const frac = s.slice(s.length - k).replace(/0+$/, '');
  return frac ? `${intPart}.${frac}` : intPart;
}

/** One row of the stability table: ξ, the reference, and each form's value and error. */
export interface StabilityRow {
  xi: number;
  quantity: 'theta' | 'phi';
  reference: number;
  forms: { id: string; value: number; relError: number; ulps: number }[];
}

/** Evaluate every form of {@link STABILITY_FORMS} at each ξ of the reference. Pure, synchronous. */
export function stabilityTable(
  ref: StabilityReference,
  forms: readonly StabilityForm[] = STABILITY_FORMS,
): StabilityRow[] {
  const rows: StabilityRow[] = [];
  for (const quantity of ['theta', 'phi'] as const) {
    ref.xi.forEach((xi, i) => {
      const reference = quantity === 'theta' ? ref.theta[i] : ref.phi[i];
      rows.push({
        xi,
        quantity,
        reference,
        forms: forms
          .filter((f) => f.quantity === quantity)
          .map((f) => {
            const e = measureError(f.fn(xi), reference);
            return { id: f.id, value: e.value, relError: e.relError, ulps: e.ulps };
          }),
      });
    });
  }
  return rows;
}
