/**
 * Analytic irradiance from a polygonal Lambertian emitter: Lambert's formula (J. H. Lambert,
 * Photometria, 1760), in the vector-irradiance form of Arvo ("Applications of Irradiance Tensors
 * to the Simulation of Non-Lambertian Phenomena", SIGGRAPH 1995, eq. 9):
 *
 *   ∫_P cos θ dω = ½ Σᵢ Γᵢ · n,   Γᵢ = θᵢ (vᵢ × vᵢ₊₁)/|vᵢ × vᵢ₊₁|,
 *
 * vᵢ the unit directions from the shading point to the polygon's vertices, θᵢ = ∠(vᵢ, vᵢ₊₁) the arc
 * length of edge i on the unit sphere, n the shading normal. The polygon is first clipped to the
 * half-space n · (x − p) ≥ 0 (the horizon): light below the horizon contributes nothing to
 * irradiance, and without the clip the cosine would count it negatively. The sign of the sum
 * depends on the winding; its absolute value is used (valid for a convex polygon, which a clipped
 * rectangle always is).
 *
 * E = L ∫ cos θ dω for a uniform emitter of radiance L seen from its emitting side, and the
 * radiance leaving a Lambertian floor of albedo ρ is L_o = (ρ/π) E.
 */
import type { RectLight } from './rectLight';
import { rectFacesPoint } from './rectLight';

/**
 * Clip a polygon (flat xyz array of vertices, relative to the shading point) to the half-space
 * n · v ≥ 0 (Sutherland–Hodgman against one plane through the origin). Returns a new flat array
 * (possibly empty). Domain: finite vertices, unit (or any nonzero) n. Source: Sutherland &
 * Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974.
 */
export function clipPolygonToHalfSpace(verts: readonly number[], nx: number, ny: number, nz: number): number[] {
  const out: number[] = [];
  const m = verts.length / 3;
  for (let i = 0; i < m; i++) {
    const j = (i + 1) % m;
    const ax = verts[3 * i]!, ay = verts[3 * i + 1]!, az = verts[3 * i + 2]!;
    const bx = verts[3 * j]!, by = verts[3 * j + 1]!, bz = verts[3 * j + 2]!;
    const da = ax * nx + ay * ny + az * nz;
    const db = bx * nx + by * ny + bz * nz;
    if (da >= 0) out.push(ax, ay, az);
    if ((da >= 0 && db < 0) || (da < 0 && db >= 0)) {
      const t = da / (da - db);
      // The point on the plane; snap its normal component to exactly 0.
      let cx = ax + t * (bx - ax), cy = ay + t * (by - ay), cz = az + t * (bz - az);
      const dc = cx * nx + cy * ny + cz * nz;
      const nn = nx * nx + ny * ny + nz * nz;
      cx -= (dc * nx) / nn; cy -= (dc * ny) / nn; cz -= (dc * nz) / nn;
      if (db !== 0) out.push(cx, cy, cz); // db = 0: b itself lies on the plane and is pushed next
    }
  }
  return out;
}

/**
 * Projected solid angle ∫_P max(0, cos θ) dω of a polygon seen from the origin, with cos θ taken
 * against the unit normal n: the polygon is clipped to n · v ≥ 0, then Lambert's formula
 * ½ |Σ θᵢ n · (vᵢ × vᵢ₊₁)/|vᵢ × vᵢ₊₁||. Domain: flat xyz vertex array of a convex planar polygon
 * relative to the shading point (any winding), unit n. Measure: projected solid angle, in [0, π].
 * Returns 0 for fewer than 3 vertices after clipping. Source: Lambert 1760; Arvo 1995.
 */
export function polygonProjectedSolidAngle(verts: readonly number[], nx = 0, ny = 0, nz = 1): number {
  const v = clipPolygonToHalfSpace(verts, nx, ny, nz);
  const m = v.length / 3;
  if (m < 3) return 0;
  let sum = 0;
  for (let i = 0; i < m; i++) {
    const j = (i + 1) % m;
    const ax = v[3 * i]!, ay = v[3 * i + 1]!, az = v[3 * i + 2]!;
    const bx = v[3 * j]!, by = v[3 * j + 1]!, bz = v[3 * j + 2]!;
    // θᵢ = atan2(|a × b|, a · b) needs no normalization (both scale by |a||b|).
    const cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    const cl = Math.hypot(cx, cy, cz);
    if (!(cl > 0)) continue; // coincident or antipodal vertices: zero-length arc (or a degenerate clip)
    const theta = Math.atan2(cl, ax * bx + ay * by + az * bz);
    sum += (theta * (cx * nx + cy * ny + cz * nz)) / cl;
  }
  const r = 0.5 * Math.abs(sum);
  return Number.isFinite(r) ? Math.min(r, Math.PI) : 0;
}

/**
 * ∫ max(0, cos θ) dω over the rectangle light seen from p with normal n (z-up default), counting
 * only the emitting side: 0 when p is behind the light or on its plane, or the light is degenerate.
 * Measure: projected solid angle (sr). Source: Lambert's formula via
 * {@link polygonProjectedSolidAngle}.
 */
export function rectProjectedSolidAngle(light: RectLight, px: number, py: number, pz: number, nx = 0, ny = 0, nz = 1): number {
  if (!rectFacesPoint(light, px, py, pz)) return 0;
  const v: number[] = [];
  for (const c of light.corners) v.push(c[0] - px, c[1] - py, c[2] - pz);
  return polygonProjectedSolidAngle(v, nx, ny, nz);
}

/**
 * The analytic reference of the area-light scene: radiance leaving a Lambertian floor point p
 * (normal +z, albedo ρ) lit by a one-sided Lambertian rectangle of radiance L, no occlusion:
 * L_o = (ρ/π) · L · ∫ max(0, cos θ) dω. Domain: finite p; L, ρ ≥ 0. Measure: radiance.
 * Source: rendering equation with f = ρ/π (exam Q6(b)); Lambert's formula for the integral.
 */
export function lambertianFloorRadiance(light: RectLight, px: number, py: number, pz: number, L: number, rho: number): number {
  return (rho / Math.PI) * L * rectProjectedSolidAngle(light, px, py, pz);
}
