/**
 * Q1's density p(ω) = k cosᵐθ e^(aφ) over the upper hemisphere (the exam's is m = 1, a = 1): the
 * parameters a seed draws (m ∈ {0, …, 4}, a a small rational ≠ 0) and the closed forms
 * (dω = sin θ dθ dφ):
 *
 *   k = a (m + 1) / (e^(2πa) − 1)                 since ∫₀^{π/2} cos^m θ sin θ dθ = 1/(m + 1)
 *   p(θ) = (m + 1) cos^m θ sin θ,  P(θ) = 1 − cos^(m+1) θ,  θ = arccos((1 − ξ₁)^(1/(m+1)))
 *   p(φ) = a e^(aφ) / (e^(2πa) − 1),  P(φ) = (e^(aφ) − 1)/(e^(2πa) − 1),  φ = ln(1 + (e^(2πa) − 1) ξ₂)/a
 *
 * e^(2πa) − 1 is evaluated as expm1(2πa), as the core's exam lobe does (core/sampling/examLobe).
 */
import { Rng } from '../core/random';
import { pick } from './build';
import { ratValue, type Rational } from './model';

const A_CHOICES: readonly Rational[] = [
  { p: 1, q: 1 },
  { p: 1, q: 1 },
  { p: 2, q: 1 },
  { p: 1, q: 2 },
  { p: 3, q: 2 },
  { p: -1, q: 1 },
  { p: -1, q: 2 },
];

/** ∫₀^{π/2} cos^m θ dθ (Wallis): π/2, 1, then (m − 1)/m times the one two below. */
export function wallis(m: number): number {
  if (m === 0) return Math.PI / 2;
  if (m === 1) return 1;
  return ((m - 1) / m) * wallis(m - 2);
}

export interface Q1Params {
  m: number;
  a: Rational;
}

export function q1Params(seed: number): Q1Params {
  const rng = new Rng(seed, 0x5101);
  const m = pick(rng, [0, 1, 1, 1, 2, 2, 3, 4]);
  const a = pick(rng, A_CHOICES);
  return { m, a };
}

/** The closed forms of a Q1 density (pure numbers and functions). */
export function q1Closed({ m, a: ar }: Q1Params) {
  const a = ratValue(ar);
  const E = Math.expm1(2 * Math.PI * a); // e^(2πa) − 1
  const k = (a * (m + 1)) / E;
  return {
    a,
    E,
    k,
    pTheta: (t: number) => (m + 1) * Math.cos(t) ** m * Math.sin(t),
    pPhi: (f: number) => (a * Math.exp(a * f)) / E,
    cdfTheta: (t: number) => 1 - Math.cos(t) ** (m + 1),
    cdfPhi: (f: number) => Math.expm1(a * f) / E,
    thetaOfXi: (x: number) => Math.acos((1 - x) ** (1 / (m + 1))),
    phiOfXi: (x: number) => Math.log1p(E * x) / a,
  };
}
