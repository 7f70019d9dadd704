/**
 * The sphere part of the texture scene (Q3 c): a point (x, y, z) mapped to (φ, θ) and to (u, v),
 * looked up normalized and not, and the angle dials' conversions.
 */
import { sphericalUV, type LookupOptions, type TextureGrid } from '../../core/texture';
import type { Failure } from '../../core/failure';
import { lookupAt, type Lookup, type TextureParams } from './model';

/** The sphere part: (x, y, z) → (φ, θ) → (u, v), looked up normalized and not. */
export type SphereModel =
  | Failure
  | {
      ok: true;
      r: number;
      phi: number;
      theta: number;
      pole: boolean;
      /** Lookup at (φ / 2π, θ / π): the exam's intended answer. */
      normalized: Lookup;
      /** Lookup at (φ, θ) in radians: the "forgot to normalize" variant. */
      raw: Lookup;
      /** The one the `normalize` parameter selects (feeds the contract readouts). */
      chosen: Lookup;
    };

export function sphereModel(
  grid: TextureGrid,
  p: Pick<TextureParams, 'x' | 'y' | 'z' | 'normalize'>,
  opts: LookupOptions,
): SphereModel {
  const s = sphericalUV(p.x, p.y, p.z);
  if (!s.ok) return s;
  const normalized = lookupAt(grid, s.u, s.v, opts);
  const raw = lookupAt(grid, s.phi, s.theta, opts);
  return {
    ok: true,
    r: s.r,
    phi: s.phi,
    theta: s.theta,
    pole: s.pole,
    normalized,
    raw,
    chosen: p.normalize ? normalized : raw,
  };
}

/** Rounded to four decimals, with −0 written as 0: how a picked or dialled sphere point is stored. */
export const round4 = (x: number): number => Math.round(x * 10000) / 10000 + 0;

/** The sphere point's azimuth φ and polar angle θ in degrees (0 where the point is unusable). */
export function sphereAnglesDeg(sphere: SphereModel): { phi: number; theta: number } {
  if (!sphere.ok) return { phi: 0, theta: 0 };
  return { phi: (sphere.phi * 180) / Math.PI, theta: (sphere.theta * 180) / Math.PI };
}

/** The point at azimuth φ and polar angle θ (degrees) on the sphere of radius r, rounded by round4. */
export function pointAtAngles(
  r: number,
  phiDeg: number,
  thetaDeg: number,
): { x: number; y: number; z: number } {
  const ph = (phiDeg * Math.PI) / 180;
  const th = (thetaDeg * Math.PI) / 180;
  return {
    x: round4(r * Math.cos(ph) * Math.sin(th)),
    y: round4(r * Math.sin(ph) * Math.sin(th)),
    z: round4(r * Math.cos(th)),
  };
}
