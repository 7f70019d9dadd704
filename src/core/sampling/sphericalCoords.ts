/**
 * Spherical coordinates in the app's frame: z-up, θ is the polar angle measured from +z
 * (θ ∈ [0, π]; the upper hemisphere is θ ∈ [0, π/2]), φ is the azimuth measured from +x towards +y
 * (φ ∈ [0, 2π)). A direction is ω = (sin θ cos φ, sin θ sin φ, cos θ).
 * Solid angle: dω = sin θ dθ dφ.
 *
 * Source: pbrt-v4, section 3.8 ("Spherical geometry"), `SphericalTheta`, `SphericalPhi`.
 */

/** Caller-owned output buffer for vectors: a Float64Array or a plain array, written at an offset. */
export type VecOut = Float64Array | number[];

/** 2π. */
export const TWO_PI = 2 * Math.PI;

/** 1/(2π). */
export const INV_TWO_PI = 1 / (2 * Math.PI);

/** π/2. */
export const HALF_PI = Math.PI / 2;

/** The largest double strictly below 2π: azimuths are clamped to it so that φ ∈ [0, 2π). */
export const TWO_PI_BELOW = 6.283185307179585; // 2π = 6.283185307179586; one ulp below

/** 1 − 2⁻⁵³, the largest double below 1: inverted samples are clamped to it so that u ∈ [0, 1). */
export const ONE_MINUS_ULP = 1 - 1 / 9007199254740992;

/**
 * Polar angle θ ∈ [0, π] of the direction (x, y, z) (need not be unit length).
 * Uses atan2(√(x²+y²), z), which is accurate near both poles, unlike acos(z) (pbrt's
 * `SphericalTheta` uses a clamped acos; atan2 keeps full relative precision for tiny θ).
 */
export function sphericalTheta(x: number, y: number, z: number): number {
  return Math.atan2(Math.hypot(x, y), z);
}

/**
 * Azimuth φ ∈ [0, 2π) of (x, y, ·), measured from +x towards +y. At the pole (x = y = 0) returns 0.
 * NaN input gives NaN. A tiny negative atan2 result would round to exactly 2π after adding 2π; it is clamped below 2π.
 */
export function sphericalPhi(x: number, y: number): number {
  const p = Math.atan2(y, x);
  if (!(p < 0)) return p; // p ≥ 0, or NaN for NaN input (callers treat it as outside the support)
  const q = p + TWO_PI;
  return q < TWO_PI ? q : TWO_PI_BELOW;
}

/**
 * Write the unit direction (sin θ cos φ, sin θ sin φ, cos θ) into out[o..o+2], given sin θ, cos θ
 * and the azimuth φ ∈ [0, 2π] (φ = 2π, which 2π·ξ can round to, is clamped one ulp below, so the
 * direction has φ ∈ [0, 2π) and inverts to a ξ below 1). Returns out. The last step of the
 * samplers that draw θ and φ separately.
 */
export function writeSphericalDirection(
  sinTheta: number,
  cosTheta: number,
  phi: number,
  out: VecOut,
  o: number,
): VecOut {
  const p = phi >= TWO_PI ? TWO_PI_BELOW : phi;
  out[o] = sinTheta * Math.cos(p);
  out[o + 1] = sinTheta * Math.sin(p);
  out[o + 2] = cosTheta;
  return out;
}

/** Clamp an inverted sample coordinate to [0, 1 − 2⁻⁵³] (NaN → 0). */
export function clampUnit(u: number): number {
  return u > 0 ? (u < ONE_MINUS_ULP ? u : ONE_MINUS_ULP) : 0;
}
