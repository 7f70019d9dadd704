/**
 * Solid-angle sampling of a rectangle: uniform density over the spherical rectangle Q that the
 * rectangle projects to on the unit sphere around a reference point p. pdf = 1/Ω per unit SOLID
 * ANGLE, Ω the rectangle's solid angle.
 *
 * Source: C. Ureña, M. Fajardo, A. King, "An Area-Preserving Parametrization for Spherical
 * Rectangles", Computer Graphics Forum 32(4) (EGSR 2013); code as in pbrt-v4
 * `SampleSphericalRectangle` / `InvertSphericalRectangleSample` (util/sampling.cpp, section 6.5.4).
 *
 * Local frame R: x along ex, y along ey, z = ±(ex × ey) chosen so the rectangle lies at z₀ < 0.
 * The rectangle is [x₀, x₁] × [y₀, y₁] at height z₀. γ₀…γ₃ are the interior angles of Q,
 * Ω = Σγᵢ − 2π. ξ₁ picks the sub-rectangle [x₀, x_u] × [y₀, y₁] whose solid angle is ξ₁ Ω (so the
 * map is area-preserving in x), ξ₂ interpolates h = y / √(x_u² + z₀² + y²) linearly (the
 * cylindrical equal-area map along the chosen great-circle arc).
 *
 * Numerics: Ω itself is computed by Van Oosterom–Strackee (see geometry/solidAngle), not by
 * Σγᵢ − 2π, which cancels for small lights. Below {@link SPHERICAL_RECT_MIN_SOLID_ANGLE} the angle
 * arithmetic of the sampler loses too many digits (its error is ~1e-16/Ω relative), so the
 * sampler falls back to uniform AREA sampling and {@link sphericalRectanglePdf} returns that
 * strategy's solid-angle density r²/(|A| cos θ_l) instead — the triple stays consistent
 * (pbrt-v4 does the same below `MinSphericalSampleArea`).
 */
import { parallelogramSolidAngle } from '../geometry/solidAngle';
import { TWO_PI } from '../sampling/sphericalCoords';
import { rectSolidAngle, type RectLight } from './rectLight';
import { sampleRectArea, type RectPointSampler } from './areaSampling';

/** Below this solid angle (sr) the sampler falls back to uniform area sampling (see file comment). */
export const SPHERICAL_RECT_MIN_SOLID_ANGLE = 1e-6;

const ONE_MINUS_EPS = 1 - 2 ** -53;

/** Precomputed state for sampling one rectangle from one reference point (build once, sample many). */
export interface SphericalRect {
  light: RectLight;
  /** Reference point p. */
  px: number;
  py: number;
  pz: number;
  /** Local frame axes in world space (z flipped so the rectangle lies at z₀ < 0). */
  xx: number;
  xy: number;
  xz: number;
  yx: number;
  yy: number;
  yz: number;
  zx: number;
  zy: number;
  zz: number;
  x0: number;
  x1: number;
  y0: number;
  y1: number;
  z0: number;
  /** z components of the edge-plane normals n₀ and n₂ (Ureña et al.'s b₀, b₁). */
  b0: number;
  b1: number;
  /** Interior angles γ₀…γ₃ of the spherical rectangle. */
  g0: number;
  g1: number;
  g2: number;
  g3: number;
  /** Solid angle Ω (Van Oosterom–Strackee), steradians. */
  solidAngle: number;
  /** True when the sampler falls back to uniform area sampling (Ω tiny but > 0). */
  areaFallback: boolean;
}

/** Angle between unit vectors, robust near 0 and π (pbrt-v4 `AngleBetween`). */
function angleBetween(ax: number, ay: number, az: number, bx: number, by: number, bz: number): number {
  const d = ax * bx + ay * by + az * bz;
  if (d < 0) return Math.PI - 2 * Math.asin(Math.min(1, Math.hypot(ax + bx, ay + by, az + bz) / 2));
  return 2 * Math.asin(Math.min(1, Math.hypot(ax - bx, ay - by, az - bz) / 2));
}

/**
 * Set up solid-angle sampling of `light` from the point p. Domain: finite p. For a degenerate
 * light or p in the light's plane, solidAngle = 0 and every sample/pdf routine returns 0 density.
 */
export function makeSphericalRect(light: RectLight, px: number, py: number, pz: number): SphericalRect {
  const ex = light.ex,
    ey = light.ey;
  let zx = ex[1] * ey[2] - ex[2] * ey[1];
  let zy = ex[2] * ey[0] - ex[0] * ey[2];
  let zz = ex[0] * ey[1] - ex[1] * ey[0];
  const s = light.corner;
  const dx = s[0] - px,
    dy = s[1] - py,
    dz = s[2] - pz;
  const x0 = dx * ex[0] + dy * ex[1] + dz * ex[2];
  const y0 = dx * ey[0] + dy * ey[1] + dz * ey[2];
  let z0 = dx * zx + dy * zy + dz * zz;
  if (z0 > 0) {
    z0 = -z0;
    zx = -zx;
    zy = -zy;
    zz = -zz;
  }
  const x1 = x0 + light.width,
    y1 = y0 + light.height;
  const omega = rectSolidAngle(light, px, py, pz);
  // Edge-plane normals in closed form (cross products of the corner vectors, normalized):
  // n0 ∝ (0, z0, −y0), n1 ∝ (−z0, 0, x1), n2 ∝ (0, −z0, y1), n3 ∝ (z0, 0, −x0).
  const l0 = Math.hypot(z0, y0),
    l1 = Math.hypot(z0, x1),
    l2 = Math.hypot(z0, y1),
    l3 = Math.hypot(z0, x0);
  let g0 = 0,
    g1 = 0,
    g2 = 0,
    g3 = 0,
    b0 = 0,
    b1 = 0;
  if (omega > 0 && l0 > 0 && l1 > 0 && l2 > 0 && l3 > 0) {
    const n0y = z0 / l0,
      n0z = -y0 / l0;
    const n1x = -z0 / l1,
      n1z = x1 / l1;
    const n2y = -z0 / l2,
      n2z = y1 / l2;
    const n3x = z0 / l3,
      n3z = -x0 / l3;
    g0 = angleBetween(0, -n0y, -n0z, n1x, 0, n1z);
    g1 = angleBetween(-n1x, 0, -n1z, 0, n2y, n2z);
    g2 = angleBetween(0, -n2y, -n2z, n3x, 0, n3z);
    g3 = angleBetween(-n3x, 0, -n3z, 0, n0y, n0z);
    b0 = n0z;
    b1 = n2z;
  }
  return {
    light,
    px,
    py,
    pz,
    xx: ex[0],
    xy: ex[1],
    xz: ex[2],
    yx: ey[0],
    yy: ey[1],
    yz: ey[2],
    zx,
    zy,
    zz,
    x0,
    x1,
    y0,
    y1,
    z0,
    b0,
    b1,
    g0,
    g1,
    g2,
    g3,
    solidAngle: omega,
    areaFallback: omega > 0 && omega < SPHERICAL_RECT_MIN_SOLID_ANGLE,
  };
}

/**
 * Sample a point on the rectangle uniformly in solid angle as seen from the reference point
 * (Ureña et al. 2013; pbrt-v4 `SampleSphericalRectangle`). Domain: u1, u2 ∈ [0, 1]. Writes the
 * point (x, y, z) on the rectangle into out[o..o+2]. Pdf per unit SOLID ANGLE:
 * {@link sphericalRectanglePdf} (1/Ω). Inverse: {@link invertSphericalRectangleSample}.
 * For Ω = 0 (nothing to sample) or Ω below {@link SPHERICAL_RECT_MIN_SOLID_ANGLE} writes the
 * uniform-area point s + u1 w ex + u2 h ey.
 */
export const sampleSphericalRectangle: RectPointSampler<SphericalRect> = (q, u1, u2, out, o = 0) => {
  if (!(q.solidAngle >= SPHERICAL_RECT_MIN_SOLID_ANGLE)) {
    sampleRectArea(q.light, u1, u2, out, o);
    return;
  }
  const { x0, x1, y0, y1, z0, b0, b1, g0, g1, g2, g3 } = q;
  // Sample x_u: the sub-rectangle [x0, x_u] × [y0, y1] has solid angle u1·Ω.
  const au = u1 * (g0 + g1 - TWO_PI) + (u1 - 1) * (g2 + g3);
  const fu = (Math.cos(au) * b0 - b1) / Math.sin(au);
  let cu = (fu < 0 ? -1 : 1) / Math.sqrt(fu * fu + b0 * b0);
  if (cu > ONE_MINUS_EPS) cu = ONE_MINUS_EPS;
  else if (cu < -ONE_MINUS_EPS) cu = -ONE_MINUS_EPS;
  if (Number.isNaN(cu)) cu = 0;
  let xu = -(cu * z0) / Math.sqrt((1 - cu) * (1 + cu));
  if (!(xu >= x0)) xu = x0;
  else if (xu > x1) xu = x1;
  // Sample y_v: h = y / √(d² + y²) is uniform between its values at y0 and y1.
  const dd2 = xu * xu + z0 * z0;
  const dd = Math.sqrt(dd2);
  const h0 = y0 / Math.sqrt(dd2 + y0 * y0);
  const h1 = y1 / Math.sqrt(dd2 + y1 * y1);
  const hv = h0 + u2 * (h1 - h0);
  const den = (1 - hv) * (1 + hv);
  let yv = den > 0 ? (hv * dd) / Math.sqrt(den) : y1;
  if (!(yv >= y0)) yv = y0;
  else if (yv > y1) yv = y1;
  out[o] = q.px + xu * q.xx + yv * q.yx + z0 * q.zx;
  out[o + 1] = q.py + xu * q.xy + yv * q.yy + z0 * q.zy;
  out[o + 2] = q.pz + xu * q.xz + yv * q.yz + z0 * q.zz;
};

/**
 * Density of {@link sampleSphericalRectangle} per unit SOLID ANGLE (of the direction from p) at the
 * point x: 1/Ω normally; r²/(|A| cos θ_l) in the tiny-light fallback (uniform area, converted);
 * 0 when Ω = 0 or when x is not on the rectangle (off its plane or outside its edges by more than
 * a relative 1e-9) — 0 outside the support, never NaN.
 */
export function sphericalRectanglePdf(q: SphericalRect, x: number, y: number, z: number): number {
  if (!(q.solidAngle > 0)) return 0;
  const l = q.light;
  const sx = x - l.corner[0],
    sy = y - l.corner[1],
    sz = z - l.corner[2];
  const tol = 1e-9 * Math.max(1, l.width, l.height, Math.abs(q.z0));
  const a = sx * l.ex[0] + sy * l.ex[1] + sz * l.ex[2];
  const b = sx * l.ey[0] + sy * l.ey[1] + sz * l.ey[2];
  const c = sx * l.normal[0] + sy * l.normal[1] + sz * l.normal[2];
  if (!(Math.abs(c) <= tol && a >= -tol && a <= l.width + tol && b >= -tol && b <= l.height + tol)) return 0;
  if (!q.areaFallback) return 1 / q.solidAngle;
  const dx = x - q.px,
    dy = y - q.py,
    dz = z - q.pz;
  const r2 = dx * dx + dy * dy + dz * dz;
  const n = l.normal;
  const r = Math.sqrt(r2);
  const cosL = r > 0 ? Math.abs(dx * n[0] + dy * n[1] + dz * n[2]) / r : 0;
  if (!(cosL > 0)) return 0;
  const v = r2 / (l.area * cosL);
  return Number.isFinite(v) ? v : 0;
}

/**
 * Inverse of {@link sampleSphericalRectangle}: the (u1, u2) ∈ [0, 1]² mapping to the point
 * (x, y, z) on the rectangle. u1 = Ω([x₀, x_u] × [y₀, y₁]) / Ω (the sub-rectangle's solid angle, by
 * Van Oosterom–Strackee, which is the defining property of the area-preserving map) and
 * u2 = (h − h₀)/(h₁ − h₀). In the tiny-light fallback, the uniform-area inverse.
 * Source: Ureña et al. 2013; pbrt-v4 `InvertSphericalRectangleSample` (same quantities).
 */
export function invertSphericalRectangleSample(
  q: SphericalRect,
  x: number,
  y: number,
  z: number,
): [number, number] {
  const dx = x - q.px,
    dy = y - q.py,
    dz = z - q.pz;
  let xu = dx * q.xx + dy * q.xy + dz * q.xz;
  let yv = dx * q.yx + dy * q.yy + dz * q.yz;
  const { x0, x1, y0, y1, z0 } = q;
  xu = Math.min(x1, Math.max(x0, xu));
  yv = Math.min(y1, Math.max(y0, yv));
  if (!(q.solidAngle >= SPHERICAL_RECT_MIN_SOLID_ANGLE)) {
    const w = x1 - x0,
      h = y1 - y0;
    return [w > 0 ? (xu - x0) / w : 0, h > 0 ? (yv - y0) / h : 0];
  }
  const sub = parallelogramSolidAngle(x0, y0, z0, xu - x0, 0, 0, 0, y1 - y0, 0);
  const u1 = Math.min(1, Math.max(0, sub / q.solidAngle));
  const dd2 = xu * xu + z0 * z0;
  const h0 = y0 / Math.sqrt(dd2 + y0 * y0);
  const h1 = y1 / Math.sqrt(dd2 + y1 * y1);
  const hv = yv / Math.sqrt(dd2 + yv * yv);
  const u2 = h1 > h0 ? Math.min(1, Math.max(0, (hv - h0) / (h1 - h0))) : 0;
  return [u1, u2];
}
