/**
 * The exam's inversion formulas (Q1(d)) in float32, as a shader evaluates them, against float64:
 *
 *   θ = ½ arccos(1 − 2ξ₁)   its twin   θ = arcsin √ξ₁,
 *   φ = ln((e^{2π} − 1) ξ₂ + 1)   and   φ = log1p((e^{2π} − 1) ξ₂).
 *
 * Every operation is rounded to float32 (Math.fround); arccos, arcsin, ln, log1p and √ are taken
 * as correctly rounded float32 functions (the double result rounded once), the best a GPU's
 * built-ins can do (GLSL allows them several ulps more). In float32 the failures the double
 * panel shows at ξ ≈ 10⁻¹⁶ arrive at ξ ≈ 10⁻⁷: 1 − 2ξ₁ rounds to 1 once ξ₁ < 2⁻²⁵ (θ = 0 for a
 * sample whose true θ is √ξ₁ ≈ 1.7·10⁻⁴), c ξ₂ + 1 swamps c ξ₂ once c ξ₂ < 2⁻²⁴, and near ξ₁ → 1
 * arcsin magnifies the rounding of √ξ₁.
 *
 * The float64 reference is the stable double form: θ = atan2(√ξ₁, √(1 − ξ₁)) and
 * φ = log1p(expm1(2π) ξ₂), accurate to a few double ulps (see ./stability.ts), i.e. exact at
 * float32 resolution.
 */
import { EXAM_E2PI_M1 } from './examLobe';
import { ulpF32 } from '../geometry/ulp32';

const fr = Math.fround;

/** e^{2π} − 1 rounded to float32 (a shader's constant). */
export const EXAM_C_F32 = fr(EXAM_E2PI_M1);

/** ½ arccos(1 − 2ξ) in float32. Domain ξ ∈ [0, 1]. */
export function thetaAcosF32(xi: number): number {
  const x = fr(xi);
  const arg = fr(1 - fr(2 * x));
  return fr(0.5 * fr(Math.acos(Math.min(1, Math.max(-1, arg)))));
}

/** arcsin √ξ in float32. Domain ξ ∈ [0, 1]. */
export function thetaAsinF32(xi: number): number {
  return fr(Math.asin(Math.min(1, fr(Math.sqrt(fr(xi))))));
}

/** ln((e^{2π} − 1) ξ + 1) in float32. Domain ξ ∈ [0, 1]. */
export function phiLnF32(xi: number): number {
  return fr(Math.log(fr(fr(EXAM_C_F32 * fr(xi)) + 1)));
}

/** log1p((e^{2π} − 1) ξ) in float32. Domain ξ ∈ [0, 1]. */
export function phiLog1pF32(xi: number): number {
  return fr(Math.log1p(fr(EXAM_C_F32 * fr(xi))));
}

/** θ(ξ) in float64, accurate to a few double ulps (the reference). */
export function thetaRef64(xi: number): number {
  return Math.atan2(Math.sqrt(xi), Math.sqrt(1 - xi));
}

/** φ(ξ) in float64 (the reference). */
export function phiRef64(xi: number): number {
  return Math.log1p(EXAM_E2PI_M1 * xi);
}

/** One ξ of the float32 table: each form's value and its error against float64. */
export interface WarpF32Row {
  /** ξ as a float32 value (the table's ξ rounded once). */
  xi: number;
  thetaRef: number;
  phiRef: number;
  forms: {
    id: 'theta-acos' | 'theta-asin' | 'phi-ln' | 'phi-log1p';
    value: number;
    /** |value − ref| / |ref| (0 when both are 0). */
    relError: number;
    /** |value − ref| in float32 ulps of the reference. */
    ulps: number;
  }[];
}

/** ξ values of the table: toward 0 and toward 1 (each rounded to float32). */
export const WARP_F32_XIS: readonly number[] = [
  2 ** -30,
  2 ** -26,
  1e-6,
  1e-4,
  1e-2,
  0.5,
  1 - 1e-2,
  1 - 1e-4,
  1 - 1e-6,
  1 - 2 ** -24,
].map(fr);

/** The float32 forms at each ξ against the float64 reference. */
export function warpF32Table(xis: readonly number[] = WARP_F32_XIS): WarpF32Row[] {
  return xis.map((x) => {
    const xi = fr(x);
    const thetaRef = thetaRef64(xi);
    const phiRef = phiRef64(xi);
    const mk = (id: WarpF32Row['forms'][number]['id'], value: number, ref: number) => {
      const e = Math.abs(value - ref);
      return { id, value, relError: ref === 0 ? e : e / Math.abs(ref), ulps: e / ulpF32(ref) };
    };
    return {
      xi,
      thetaRef,
      phiRef,
      forms: [
        mk('theta-acos', thetaAcosF32(xi), thetaRef),
        mk('theta-asin', thetaAsinF32(xi), thetaRef),
        mk('phi-ln', phiLnF32(xi), phiRef),
        mk('phi-log1p', phiLog1pF32(xi), phiRef),
      ],
    };
  });
}

/**
 * The GPU pass's random numbers, emulated: PCG's output hash ("PCG-RXS-M-XS", as in Jarzynski &
 * Olano, "Hash Functions for GPU Rendering", JCGT 2020) of the vertex index mixed with the seed,
 * and a second hash for ξ₂; each ξ keeps the hash's top 24 bits, ξ = k·2⁻²⁴ ∈ [0, 1 − 2⁻²⁴],
 * exactly representable in float32.
 */
export function pcgHash(v: number): number {
  const state = (Math.imul(v >>> 0, 747796405) + 2891336453) >>> 0;
  const word = Math.imul(((state >>> ((state >>> 28) + 4)) ^ state) >>> 0, 277803737) >>> 0;
  return ((word >>> 22) ^ word) >>> 0;
}

/** ξ₁, ξ₂ of GPU sample i for a seed (the same as the vertex shader computes). */
export function gpuXi(i: number, seed: number): [number, number] {
  const h1 = pcgHash((i ^ pcgHash(seed >>> 0)) >>> 0);
  const h2 = pcgHash(h1);
  return [(h1 >>> 8) * 2 ** -24, (h2 >>> 8) * 2 ** -24];
}
