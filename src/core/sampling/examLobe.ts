/**
 * The exam's lobe (Q1): p(ω) = k cos θ e^φ over the upper hemisphere, per unit solid angle,
 * θ ∈ [0, π/2] from +z, φ ∈ [0, 2π) from +x (z-up).
 *
 * Derivation (the scene's derivation panel walks the same steps):
 *  (a) ∫ p dω = k ∫₀^{π/2} cos θ sin θ dθ ∫₀^{2π} e^φ dφ = k · ½ · (e^{2π} − 1) = 1
 *      ⇒ k = 2/(e^{2π} − 1), computed as 2/expm1(2π).
 *  (b) p(θ, φ) = sin θ · p(ω) = k sin θ cos θ e^φ — separable:
 *      p(θ) = sin 2θ on [0, π/2], p(φ) = e^φ/(e^{2π} − 1) on [0, 2π).
 *  (c) P(θ) = (1 − cos 2θ)/2 = sin²θ, P(φ) = (e^φ − 1)/(e^{2π} − 1) = expm1(φ)/expm1(2π).
 *  (d) θ = ½ arccos(1 − 2ξ₁) = arcsin √ξ₁; φ = ln((e^{2π} − 1) ξ₂ + 1) = log1p(expm1(2π) ξ₂).
 *
 * Stable form used here. With cos 2θ = 1 − 2ξ₁ the half-angle identities give
 *   cos²θ = (1 + cos 2θ)/2 = 1 − ξ₁,   sin²θ = (1 − cos 2θ)/2 = ξ₁,
 * so sin θ = √ξ₁ and cos θ = √(1 − ξ₁) with no trigonometric call at all. Both are accurate to
 * ~1 ulp everywhere: √ξ₁ keeps full relative precision for tiny ξ₁ (where 1 − 2ξ₁ rounds to 1 and
 * ½ arccos(1 − 2ξ₁) returns 0), and 1 − ξ₁ is exact for every ξ₁ = k·2⁻⁵³ the generator returns
 * (and for all ξ₁ ≥ ½ by Sterbenz), so cos θ is accurate near the horizon (where arcsin √ξ₁ is
 * ill-conditioned). For φ, log1p(expm1(2π) ξ₂) keeps relative precision for tiny ξ₂, where
 * ln(c ξ₂ + 1) loses it (c ξ₂ + 1 rounds to 1). φ is clamped below 2π so that φ ∈ [0, 2π).
 *
 * Source: the exam key (Q1); inversion method, pbrt-v4 section 2.3 ("Sampling using the inversion
 * method"); 2D sampling with separable densities, pbrt-v4 section 2.4.1.
 */
import { writeScaledCosSin } from './sinCos';
import { TWO_PI, TWO_PI_BELOW, HALF_PI, clampUnit, sphericalPhi, type VecOut } from './sphericalCoords';

/** e^{2π} − 1 computed as expm1(2π) (≈ 534.49). */
export const EXAM_E2PI_M1 = Math.expm1(TWO_PI);

const K = 2 / EXAM_E2PI_M1;

/**
 * k = 2/(e^{2π} − 1) ≈ 3.742e-3, the normalization constant of p(ω) = k cos θ e^φ over the upper
 * hemisphere with respect to solid angle, computed as 2/expm1(2π). Source: exam key Q1(a).
 */
export function examLobeK(): number {
  return K;
}

/**
 * Sample the exam lobe by inversion. Domain: u1, u2 ∈ [0, 1). Writes the unit vector
 * (sin θ cos φ, sin θ sin φ, cos θ) into out[o..o+2], with sin θ = √u1, cos θ = √(1 − u1) and
 * φ = log1p(expm1(2π) u2) clamped below 2π (see the module comment for why this form is stable).
 * Measure: solid angle; pdf {@link examLobePdf}. Source: exam key Q1(d); pbrt-v4 2.3.
 */
export function sampleExamLobe(u1: number, u2: number, out: VecOut, o = 0): VecOut {
  const s = Math.sqrt(u1);
  const c = Math.sqrt(1 - u1);
  let phi = Math.log1p(EXAM_E2PI_M1 * u2);
  if (phi >= TWO_PI) phi = TWO_PI_BELOW;
  writeScaledCosSin(phi, s, out, o);
  out[o + 2] = c;
  return out;
}

/**
 * Batched {@link sampleExamLobe}: reads u[2i] (ξ₁), u[2i+1] (ξ₂), writes the unit vector to
 * out[3i..3i+2] for i ∈ [start, n). Caller-owned buffers; no allocation, no object per sample.
 * Measure: solid angle. This is the hot path the benchmark measures.
 */
export function sampleExamLobeBatch(u: Float64Array, out: Float64Array, n: number, start = 0): Float64Array {
  for (let i = start; i < n; i++) sampleExamLobe(u[2 * i], u[2 * i + 1], out, 3 * i);
  return out;
}

/**
 * Density of {@link sampleExamLobe} per unit solid angle at the unit direction (x, y, z):
 * k cos θ e^φ with cos θ = z and φ = azimuth of (x, y) in [0, 2π). Returns 0 for z ≤ 0 (outside
 * the open upper hemisphere, where cos θ ≤ 0) and for NaN input. Source: exam key Q1.
 */
export function examLobePdf(x: number, y: number, z: number): number {
  if (!(z > 0)) return 0;
  const phi = sphericalPhi(x, y);
  if (!Number.isFinite(phi)) return 0;
  return K * z * Math.exp(phi);
}

/**
 * Density of the exam lobe in the (θ, φ) parametrization, per unit dθ dφ:
 * p(θ, φ) = sin θ · p(ω) = k sin θ cos θ e^φ on [0, π/2] × [0, 2π), 0 elsewhere.
 * Source: exam key Q1(b) (the correct Jacobian).
 */
export function examLobeThetaPhiPdf(theta: number, phi: number): number {
  if (!(theta >= 0 && theta <= HALF_PI && phi >= 0 && phi < TWO_PI)) return 0;
  return K * Math.sin(theta) * Math.cos(theta) * Math.exp(phi);
}

/**
 * Inverse of {@link sampleExamLobe}: the (ξ₁, ξ₂) ∈ [0, 1)² that maps to the direction (x, y, z)
 * (z ≥ 0; need not be exactly unit length). ξ₁ = sin²θ = (x² + y²)/(x² + y² + z²) (accurate near
 * the pole, unlike 1 − z²), ξ₂ = P(φ) = expm1(φ)/expm1(2π). Source: exam key Q1(c).
 */
export function invertExamLobeSample(x: number, y: number, z: number): [number, number] {
  const rho2 = x * x + y * y;
  const len2 = rho2 + z * z;
  const xi1 = len2 > 0 ? rho2 / len2 : 0;
  const xi2 = Math.expm1(sphericalPhi(x, y)) / EXAM_E2PI_M1;
  return [clampUnit(xi1), clampUnit(xi2)];
}

/** Marginal density of θ, p(θ) = sin 2θ on [0, π/2], 0 elsewhere (per unit θ). Exam key Q1(b). */
export function examThetaPdf(theta: number): number {
  return theta >= 0 && theta <= HALF_PI ? Math.sin(2 * theta) : 0;
}

/** Marginal CDF of θ, P(θ) = sin²θ (= (1 − cos 2θ)/2), clamped to 0 below 0 and 1 above π/2. Q1(c). */
export function examThetaCdf(theta: number): number {
  if (!(theta > 0)) return 0;
  if (theta >= HALF_PI) return 1;
  const s = Math.sin(theta);
  return s * s;
}

/** Marginal density of φ, p(φ) = e^φ/(e^{2π} − 1) on [0, 2π), 0 elsewhere (per unit φ). Q1(b). */
export function examPhiPdf(phi: number): number {
  return phi >= 0 && phi < TWO_PI ? Math.exp(phi) / EXAM_E2PI_M1 : 0;
}

/** Marginal CDF of φ, P(φ) = expm1(φ)/expm1(2π), clamped to [0, 1]. Q1(c). */
export function examPhiCdf(phi: number): number {
  if (!(phi > 0)) return 0;
  if (phi >= TWO_PI) return 1;
  return Math.expm1(phi) / EXAM_E2PI_M1;
}

/**
 * The key's upside-down Jacobian variant, p̃(θ, φ) = p(ω)/sin θ = k cot θ e^φ (per unit dθ dφ).
 * It is NOT a density: ∫₀^{π/2} cot θ dθ diverges at θ → 0. Returns the (finite) value for
 * θ ∈ (0, π/2], φ ∈ [0, 2π), +∞ at θ = 0, 0 outside. Used only to show why it fails.
 */
export function invertedJacobianDensity(theta: number, phi: number): number {
  if (!(theta >= 0 && theta <= HALF_PI && phi >= 0 && phi < TWO_PI)) return 0;
  if (theta === 0) return Infinity;
  return (K * Math.exp(phi)) / Math.tan(theta);
}

/**
 * Partial integral of the inverted variant's θ factor, ∫_ε^{π/2} cot θ dθ = −ln sin ε, for
 * ε ∈ (0, π/2]. It grows without bound as ε → 0 (like −ln ε), which is why the variant cannot be
 * normalized. Returns +∞ for ε ≤ 0 and 0 for ε ≥ π/2; NaN input gives NaN (callers validate).
 */
export function invertedJacobianPartialIntegral(eps: number): number {
  if (eps <= 0) return Infinity;
  if (eps >= HALF_PI) return 0;
  return -Math.log(Math.sin(eps));
}
