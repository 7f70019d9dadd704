/**
 * Helpers for follow-through rules: reading a student's own earlier answers and comparing a later
 * answer with what those answers give. A student's own numbers are often rounded, so these
 * comparisons are looser than grading ({@link FOLLOW_RTOL}); they only ever decide partial credit for
 * an answer that is not right.
 */
import { integrate1D } from '../core/verify';
import { formulaPoints } from './check';
import type { Fn, OwnValue } from './model';

/** Relative tolerance of a follow-through comparison (the student's own rounded numbers). */
export const FOLLOW_RTOL = 5e-3;

export function ownNumber(own: Readonly<Record<string, OwnValue>>, name: string): number | null | undefined {
  const x = own[name];
  return x === null || typeof x === 'number' ? x : undefined;
}

export function ownFn(own: Readonly<Record<string, OwnValue>>, name: string): Fn | undefined {
  const x = own[name];
  return typeof x === 'function' ? x : undefined;
}

/** Whether x is y to follow-through precision (null = "none"). */
export function closeTo(x: OwnValue, y: number | null | undefined): boolean {
  if (y === undefined) return false;
  if (x === null || y === null) return x === y;
  if (typeof x !== 'number' || !Number.isFinite(y)) return false;
  return Math.abs(x - y) <= FOLLOW_RTOL * Math.abs(y) + 1e-9;
}

/**
 * Whether g agrees with f at the comparison points of a 1-D domain, to follow-through precision.
 * Points where f is not finite are skipped (at least half must remain).
 */
export function closeFns(f: Fn, g: OwnValue, domain: readonly [number, number]): boolean {
  if (typeof g !== 'function') return false;
  const pts = formulaPoints([domain], 24);
  const fv = pts.map((p) => f(p[0]));
  const scale = Math.max(0, ...fv.filter(Number.isFinite).map(Math.abs));
  if (!(scale > 0)) return false;
  let used = 0;
  for (let i = 0; i < pts.length; i++) {
    if (!Number.isFinite(fv[i])) continue;
    const y = g(pts[i][0]);
    if (!Number.isFinite(y)) return false;
    if (Math.abs(y - fv[i]) > FOLLOW_RTOL * Math.max(Math.abs(fv[i]), 1e-3 * scale)) return false;
    used++;
  }
  return used >= pts.length / 2;
}

/** x ↦ ∫₀ˣ g (adaptive quadrature); NaN where the integral does not converge. */
export function integralFrom0(g: Fn): Fn {
  return (x: number) => {
    const r = integrate1D((t) => g(t), 0, x, { relTol: 1e-10, maxIntervals: 200 });
    return r.converged && Number.isFinite(r.value) ? r.value : NaN;
  };
}
