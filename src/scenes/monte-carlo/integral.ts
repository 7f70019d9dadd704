/**
 * The reference value of ∫ₐᵇ f dx the scene compares every estimate with: in closed form for
 * (x + c)², else by adaptive quadrature, with the reason when it has none; and the limits' check.
 */
import { integrate1D, INTEGRATION_METHOD } from '../../core/verify/integrate1d';
import { formatPlain } from '../../core/format';
import type { ParamProblem } from '../../kit/params';

/** The exam's limits of integration, and the ones a scene falls back to when a ≥ b. */
export const EXAM_A = 0;
export const EXAM_B = 2;

/** A real function of x (compiled user expression or closed form). */
export type Fn1 = (x: number) => number;

/**
 * The limits the scene uses: a and b as given when a < b, else the exam's [0, 2], with the message
 * the page shows and the problem the shell reports (named after b, the limit read last).
 */
export function checkLimits(
  a: number,
  b: number,
): { a: number; b: number; message: string | null; problem: ParamProblem | null } {
  if (Number.isFinite(a) && Number.isFinite(b) && a < b) return { a, b, message: null, problem: null };
  const message = `The limits must satisfy a < b (got a = ${a}, b = ${b}); using [${EXAM_A}, ${EXAM_B}].`;
  return { a: EXAM_A, b: EXAM_B, message, problem: { name: 'b', message: `and a: ${message}` } };
}

/**
 * If the source is (x + c)^2 (spaces, ** and a leading + ignored), return c, else null: then p ∝ f
 * has the closed form p = 3(x + c)²/((b + c)³ − (a + c)³) and the integral is exact.
 */
export function squareShift(src: string): number | null {
  const s = src.replace(/\s+/g, '').replace(/\*\*/g, '^');
  const m = /^\(x([+-])(\d+(?:\.\d*)?(?:e[+-]?\d+)?)\)\^2$/i.exec(s);
  if (m) {
    const c = Number(m[2]);
    return Number.isFinite(c) ? (m[1] === '-' ? -c : c) : null;
  }
  if (s === 'x^2') return 0;
  return null;
}

/** Reference value of ∫ₐᵇ f dx with the method that produced it. */
export interface Exact {
  value: number;
  /** Method, named for the page. */
  method: string;
  /** Estimated absolute error of `value` (0 for closed forms). */
  error: number;
  /** Why there is no value (non-finite f, divergent integral). */
  problem: string | null;
}

/**
 * ∫ₐᵇ f dx: closed form ((b + c)³ − (a + c)³)/3 when f is (x + c)², else adaptive Gauss–Kronrod
 * to full precision (core/verify/integrate1d).
 */
export function exactIntegral(fSrc: string, f: Fn1, a: number, b: number): Exact {
  const c = squareShift(fSrc);
  if (c !== null) {
    const A = a + c;
    const B = b + c;
    return {
      value: ((b - a) * (B * B + A * B + A * A)) / 3,
      method: 'closed form ((b + c)³ − (a + c)³)/3',
      error: 0,
      problem: null,
    };
  }
  const r = integrate1D(f, a, b);
  if (r.nonFiniteAt !== undefined) {
    return {
      value: NaN,
      method: INTEGRATION_METHOD,
      error: Infinity,
      problem: `f is not finite at x = ${formatPlain(r.nonFiniteAt)}, so ∫ f dx has no value on [${formatPlain(a)}, ${formatPlain(b)}].`,
    };
  }
  if (!r.converged) {
    return {
      value: NaN,
      method: INTEGRATION_METHOD,
      error: r.error,
      problem: `∫ f dx over [${formatPlain(a)}, ${formatPlain(b)}] does not converge (the quadrature error does not shrink): the integral may diverge.`,
    };
  }
  return {
    value: r.value,
    method: `${INTEGRATION_METHOD}, ${r.evaluations} evaluations, error ≤ ${r.error.toExponential(1)}`,
    error: r.error,
    problem: null,
  };
}
