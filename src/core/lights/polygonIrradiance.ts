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
 * Folds visit(acc, a, b) over the edges of a polygon given as a flat xyz array of m vertices: the
 * edges (vertex i, vertex i + 1), i = 0 … m − 1, in that order, the last one closing the polygon
 * back to vertex 0. Returns the last accumulator.
 */
function reduceEdges<T>(
  verts: readonly number[],
  acc: T,
  visit: (acc: T, ax: number, ay: number, az: number, bx: number, by: number, bz: number) => T,
): T {
  const m = verts.length / 3;
  for (let i = 0; i < m; i++) {
    const j = (i + 1) % m;
    acc = visit(
      acc,
      verts[3 * i],
      verts[3 * i + 1],
      verts[3 * i + 2],
      verts[3 * j],
      verts[3 * j + 1],
      verts[3 * j + 2],
    );
  }
  return acc;
}

/**
 * Clip a polygon (flat xyz array of vertices, relative to the shading point) to the half-space
 * n · v ≥ offset (Sutherland–Hodgman against one plane; offset 0: a plane through the origin).
 * Returns a new flat array (possibly empty). Domain: finite vertices, nonzero n. Source:
 * Sutherland & Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974.
 */
export function clipPolygonToHalfSpace(
  verts: readonly number[],
  nx: number,
  ny: number,
  nz: number,
  offset = 0,
): number[] {
  return reduceEdges(verts, [] as number[], (out, ax, ay, az, bx, by, bz) => {
    const da = ax * nx + ay * ny + az * nz - offset;
    const db = bx * nx + by * ny + bz * nz - offset;
    if (da >= 0) out.push(ax, ay, az);
    if ((da >= 0 && db < 0) || (da < 0 && db >= 0)) {
      const t = da / (da - db);
      // The point on the plane; snap its normal component to exactly 0.
      let cx = ax + t * (bx - ax),
        cy = ay + t * (by - ay),
        cz = az + t * (bz - az);
      const dc = cx * nx + cy * ny + cz * nz - offset;
      const nn = nx * nx + ny * ny + nz * nz;
      cx -= (dc * nx) / nn;
      cy -= (dc * ny) / nn;
      cz -= (dc * nz) / nn;
      if (db !== 0) out.push(cx, cy, cz); // db = 0: b itself lies on the plane and is pushed next
    }
    return out;
  });
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
  const sum = reduceEdges(v, 0, (sum, ax, ay, az, bx, by, bz) => {
    // θᵢ = atan2(|a × b|, a · b) needs no normalization (both scale by |a||b|).
    const cx = ay * bz - az * by,
      cy = az * bx - ax * bz,
      cz = ax * by - ay * bx;
    const cl = Math.hypot(cx, cy, cz);
    if (!(cl > 0)) return sum; // coincident or antipodal vertices: zero-length arc (or a degenerate clip)
    const theta = Math.atan2(cl, ax * bx + ay * by + az * bz);
    return sum + (theta * (cx * nx + cy * ny + cz * nz)) / cl;
  });
  const r = 0.5 * Math.abs(sum);
  return Number.isFinite(r) ? Math.min(r, Math.PI) : 0;
}

/**
 * ∫ max(0, cos θ) dω over the rectangle light seen from p with normal n (z-up default), counting
 * only the emitting side: 0 when p is behind the light or on its plane, or the light is degenerate.
 * Measure: projected solid angle (sr). Source: Lambert's formula via
 * {@link polygonProjectedSolidAngle}.
 */
export function rectProjectedSolidAngle(
  light: RectLight,
  px: number,
  py: number,
  pz: number,
  nx = 0,
  ny = 0,
  nz = 1,
): number {
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
export function lambertianFloorRadiance(
  light: RectLight,
  px: number,
  py: number,
  pz: number,
  L: number,
  rho: number,
): number {
  return (rho / Math.PI) * L * rectProjectedSolidAngle(light, px, py, pz);
}

/**
 * Sutherland–Hodgman clip of a 2D polygon (flat xy array) to the axis-aligned box
 * [0, w] × [0, h]. Returns a new flat array (possibly empty). Source: Sutherland & Hodgman 1974.
 */
export function clipPolygonToBox(poly: readonly number[], w: number, h: number): number[] {
  let cur = poly.slice();
  // Each clip edge as (axis, bound, keepBelow).
  const edges: Array<[0 | 1, number, boolean]> = [
    [0, 0, false],
    [0, w, true],
    [1, 0, false],
    [1, h, true],
  ];
  for (const [ax, bound, below] of edges) {
    const inside = (x: number, y: number) => {
      const v = ax === 0 ? x : y;
      return below ? v <= bound : v >= bound;
    };
    const out: number[] = [];
    const m = cur.length / 2;
    for (let i = 0; i < m; i++) {
      const j = (i + 1) % m;
      const x1 = cur[2 * i],
        y1 = cur[2 * i + 1],
        x2 = cur[2 * j],
        y2 = cur[2 * j + 1];
      const in1 = inside(x1, y1),
        in2 = inside(x2, y2);
      if (in1) out.push(x1, y1);
      if (in1 !== in2) {
        const v1 = ax === 0 ? x1 : y1,
          v2 = ax === 0 ? x2 : y2;
        const t = (bound - v1) / (v2 - v1);
        if (ax === 0) out.push(bound, y1 + t * (y2 - y1));
        else out.push(x1 + t * (x2 - x1), bound);
      }
    }
    cur = out;
    if (cur.length < 6) return [];
  }
  return cur;
}

/** Rays parallel to the light's plane within this fraction of p's distance are not projected. */
const SLAB_EPS = 1e-7;

/**
 * ∫ max(0, cos θ) V dω over the rectangle light seen from p (normal +z) with a rectangular
 * occluder. Only the part of the occluder between p and the light's plane can block it, so the
 * occluder is first clipped to that slab (0 < distance towards the light ≤ p's distance to the
 * plane; the near side is cut at a relative 1e-7 so no ray parallel to the plane is projected);
 * the clipped polygon's shadow on the light's plane is its central projection from p (convex);
 * the visible part of the light is the light minus that shadow clipped to the light, and by
 * additivity ∫_visible = ∫_light − ∫_(light ∩ shadow), each by Lambert's formula (with the horizon
 * clip). Domain: any placement (an occluder beyond the light or behind p casts no shadow).
 * Measure: projected solid angle. Source: Lambert 1760 / Arvo 1995 (polygon irradiance),
 * Sutherland–Hodgman clipping.
 */
export function rectProjectedSolidAngleOccluded(
  light: RectLight,
  occluder: RectLight,
  px: number,
  py: number,
  pz: number,
): number {
  const base = rectProjectedSolidAngle(light, px, py, pz);
  if (base === 0 || !(occluder.area > 0)) return base;
  // m = −n_l points from p towards the light's plane; sigma = p's distance to the plane (> 0 here).
  const mx = -light.normal[0],
    my = -light.normal[1],
    mz = -light.normal[2];
  const sigma = (light.center[0] - px) * mx + (light.center[1] - py) * my + (light.center[2] - pz) * mz;
  let v: number[] = [];
  for (const c of occluder.corners) v.push(c[0] - px, c[1] - py, c[2] - pz);
  v = clipPolygonToHalfSpace(v, mx, my, mz, SLAB_EPS * sigma);
  v = clipPolygonToHalfSpace(v, -mx, -my, -mz, -sigma);
  if (v.length < 9) return base;
  const poly2: number[] = [];
  for (let i = 0; i < v.length; i += 3) {
    const h = v[i] * mx + v[i + 1] * my + v[i + 2] * mz;
    const t = sigma / h; // ≥ 1: the ray through the occluder point meets the plane at p + t v
    const hx = px + t * v[i] - light.corner[0],
      hy = py + t * v[i + 1] - light.corner[1],
      hz = pz + t * v[i + 2] - light.corner[2];
    poly2.push(
      hx * light.ex[0] + hy * light.ex[1] + hz * light.ex[2],
      hx * light.ey[0] + hy * light.ey[1] + hz * light.ey[2],
    );
  }
  const clipped = clipPolygonToBox(poly2, light.width, light.height);
  if (clipped.length < 6) return base;
  const w: number[] = [];
  for (let i = 0; i < clipped.length; i += 2) {
    const a = clipped[i],
      b = clipped[i + 1];
    for (let k = 0; k < 3; k++)
      w.push(light.corner[k] + a * light.ex[k] + b * light.ey[k] - (k === 0 ? px : k === 1 ? py : pz));
  }
  return Math.max(0, base - polygonProjectedSolidAngle(w));
}
