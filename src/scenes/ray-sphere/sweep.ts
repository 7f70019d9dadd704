/**
 * The sweep animation: the ray moves across the sphere as the timeline's t goes 0 → 1. Everything
 * on screen at position t is a pure function of the parameters and t.
 */
import { dot, norm, scale, sub, type Vec3 } from '../../core/vec3';
import { canonicalFrame, closestOffset } from './frame';
import type { InputCheck } from './inputs';
import type { RaySphereParams } from './params';

export type SweepMode = 'offset' | 'rotate';

export interface Sweep {
  mode: SweepMode;
  /** Extent E: the origin moves ±E r (offset), or the direction turns ±E α (rotate). */
  extent: number;
  /** The configuration the sweep is centred on (t = 0.5): the checked inputs. */
  base: InputCheck;
  /** In-plane frame of the base configuration: e1 = d / |d|, e2 from C towards the line. */
  e1: Vec3;
  e2: Vec3;
  /** Signed distance of the base line from C along e2 (= |l| ≥ 0). */
  h0: number;
  /** |d| and |o − C| of the base configuration. */
  dl: number;
  dist: number;
  /** The sphere's angular radius seen from o: asin(min(1, r / |o − C|)); π/2 from inside. */
  alpha: number;
  /** Angle (in the e1, e2 plane) of the direction from o towards C. */
  omega: number;
}

/** The sweep's frame and constants for one parameter set (t-independent). */
export function makeSweep(input: InputCheck, mode: SweepMode, extent: number): Sweep {
  const { o, d, c, r } = input;
  const fr = canonicalFrame(o, d, c);
  const f = sub(o, c);
  const dist = norm(f);
  // l = f − (f·d / d·d) d: from C to the closest point of the line (as in the robust form); its
  // length is the line's distance from C. e2 = l / |l|, made exactly perpendicular to e1 again
  // (for a far sphere l's direction carries the rounding of f·d, and f·e2 would cancel to 0).
  const e1 = fr.e1;
  const l = closestOffset(o, d, c);
  const h0 = norm(l);
  let e2: Vec3 = fr.e2;
  if (h0 > 0 && Number.isFinite(h0)) {
    let w = scale(l, 1 / h0);
    w = sub(w, scale(e1, dot(w, e1)));
    const wn = norm(w);
    if (wn > 0.5) e2 = scale(w, 1 / wn);
  }
  const alpha = dist > r ? Math.asin(r / dist) : Math.PI / 2;
  // direction from o to C in the (e1, e2) plane: −f = −(f·e1) e1 − h0 e2
  const omega = Math.atan2(-h0, -dot(f, e1));
  return {
    mode,
    extent: Number.isFinite(extent) && extent > 0 ? extent : 2.5,
    base: input,
    e1,
    e2,
    h0,
    dl: norm(d),
    dist,
    alpha,
    omega,
  };
}

export interface SweepState {
  t: number;
  o: Vec3;
  d: Vec3;
  /**
   * The sweep coordinate drawn on the Δ plot's x axis. Offset: the signed distance of the line
   * from C in radii, h / r (tangent at ±1). Rotate: the angle between d and the direction to C in
   * angular radii, ψ / α (tangent at ±1 when the origin is outside).
   */
  x: number;
}

/** Where the ray is at timeline position t ∈ [0, 1] (t = 0.5: the configuration typed in o, d). */
export function sweepAt(sw: Sweep, t: number): SweepState {
  const u = 2 * Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0.5)) - 1;
  const { o, d, r } = sw.base;
  if (u === 0) {
    // exactly the typed configuration (no rounding from adding zero offsets)
    return {
      t,
      o: [o[0], o[1], o[2]],
      d: [d[0], d[1], d[2]],
      x: sw.mode === 'offset' ? sw.h0 / r : psi(sw, 0),
    };
  }
  if (sw.mode === 'offset') {
    const s = u * sw.extent * r;
    return {
      t,
      o: [o[0] + s * sw.e2[0], o[1] + s * sw.e2[1], o[2] + s * sw.e2[2]],
      d: [d[0], d[1], d[2]],
      x: (sw.h0 + s) / r,
    };
  }
  const th = u * sw.extent * sw.alpha;
  const cs = Math.cos(th) * sw.dl;
  const sn = Math.sin(th) * sw.dl;
  return {
    t,
    o: [o[0], o[1], o[2]],
    d: [cs * sw.e1[0] + sn * sw.e2[0], cs * sw.e1[1] + sn * sw.e2[1], cs * sw.e1[2] + sn * sw.e2[2]],
    x: psi(sw, th),
  };
}

/** Angle between the direction at in-plane angle θ and the direction to C, in angular radii, in (−π/α, π/α]. */
function psi(sw: Sweep, theta: number): number {
  let p = theta - sw.omega;
  p = Math.atan2(Math.sin(p), Math.cos(p));
  return p / sw.alpha;
}

/** The sweep range of x (the Δ plot's axis), from t = 0 to t = 1 (may decrease). */
export function sweepXRange(sw: Sweep): [number, number] {
  return [sweepAt(sw, 0).x, sweepAt(sw, 1).x];
}

/** The scene's parameters with the ray moved to timeline position t (for computeModel). */
export function paramsAt(p: RaySphereParams, sw: Sweep, t: number): RaySphereParams {
  const s = sweepAt(sw, t);
  return { ...p, o: [...s.o], d: [...s.d] };
}
