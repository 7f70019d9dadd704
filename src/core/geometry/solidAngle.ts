/**
 * Solid angles of planar triangles and parallelograms seen from a point, robust for tiny and
 * distant shapes, and the small-patch approximation dω ≈ dA cos θ_l / r² that exam Q6(a) derives.
 *
 * Formula: Van Oosterom & Strackee, "The solid angle of a plane triangle", IEEE Trans. Biomed. Eng.
 * BME-30(2), 1983:  tan(Ω/2) = |a·(b×c)| / (abc + (a·b)c + (a·c)b + (b·c)a), with a, b, c the vectors
 * from the viewpoint to the vertices and a, b, c (plain) their lengths. Evaluated with atan2, so
 * Ω ∈ [0, 2π] with no branch for an obtuse denominator.
 *
 * Robustness: the triple product is computed as a·(e₁×e₂) from the vertex a and the two EDGE
 * vectors e₁ = b − a, e₂ = c − a (which the caller knows exactly), not as a·(b×c): for a light of
 * size s at distance D ≫ s, b×c of two nearly parallel long vectors loses log10(D/s) digits,
 * whereas e₁×e₂ is exact-ish and the denominator is a sum of positive terms. So Ω stays accurate
 * to a few ulps relative even at D = 1e8·s, where Ω ≈ 1e-16.
 */

/** A 3-vector as a tuple (not used on hot paths). */
export type Vec3Like = readonly [number, number, number] | Float64Array | readonly number[];

/**
 * Solid angle (steradians) subtended at the origin by the triangle with vertex a and edges
 * e₁ = b − a, e₂ = c − a (all relative to the viewpoint). Domain: any finite vectors. Measure:
 * solid angle, in [0, 2π]; 0 for a degenerate triangle or a viewpoint in the triangle's plane.
 * Source: Van Oosterom & Strackee 1983, with the triple product taken over edges (see file comment).
 */
export function triangleSolidAngleEdges(
  ax: number,
  ay: number,
  az: number,
  e1x: number,
  e1y: number,
  e1z: number,
  e2x: number,
  e2y: number,
  e2z: number,
): number {
  const bx = ax + e1x,
    by = ay + e1y,
    bz = az + e1z;
  const cx = ax + e2x,
    cy = ay + e2y,
    cz = az + e2z;
  const la = Math.hypot(ax, ay, az);
  const lb = Math.hypot(bx, by, bz);
  const lc = Math.hypot(cx, cy, cz);
  // The triple product a·(e₁×e₂) over the edges (see the file comment).
  const nx = e1y * e2z - e1z * e2y;
  const ny = e1z * e2x - e1x * e2z;
  const nz = e1x * e2y - e1y * e2x;
  const num = Math.abs(ax * nx + ay * ny + az * nz);
  if (!(num > 0)) return 0;
  const den =
    la * lb * lc +
    (ax * bx + ay * by + az * bz) * lc +
    (ax * cx + ay * cy + az * cz) * lb +
    (bx * cx + by * cy + bz * cz) * la;
  const omega = 2 * Math.atan2(num, den);
  return Number.isFinite(omega) ? omega : 0;
}

/**
 * Solid angle of the triangle (a, b, c), vertices given relative to the viewpoint.
 * Convenience over {@link triangleSolidAngleEdges}; prefer that when the edges are known exactly
 * (tiny, distant triangles). Measure: steradians in [0, 2π]. Source: Van Oosterom & Strackee 1983.
 */
export function triangleSolidAngle(a: Vec3Like, b: Vec3Like, c: Vec3Like): number {
  return triangleSolidAngleEdges(
    a[0],
    a[1],
    a[2],
    b[0] - a[0],
    b[1] - a[1],
    b[2] - a[2],
    c[0] - a[0],
    c[1] - a[1],
    c[2] - a[2],
  );
}

/**
 * Solid angle subtended at the origin by the parallelogram with corner d (relative to the
 * viewpoint) and full edge vectors ex, ey. Domain: finite vectors; measure: steradians in [0, 2π];
 * 0 when degenerate (zero area) or when the viewpoint lies in the plane (seen edge-on).
 *
 * How: if the foot F of the perpendicular from the viewpoint lies inside the parallelogram, fan four
 * triangles (F, Vᵢ, Vᵢ₊₁) from it; otherwise split along a diagonal into (d, d+ex, d+ex+ey) and
 * (d, d+ex+ey, d+ey). Each triangle by Van Oosterom–Strackee with exact edge vectors. The fan
 * avoids an artificial ill-conditioning of the diagonal split: a viewpoint very close to the plane
 * above the diagonal sees each half as nearly π, where the denominator cancels (1e-11 relative
 * error at height 1e-6); with the fan only the real edges can be near F, where the problem itself
 * is ill-conditioned. For a viewpoint off the plane all triangles are seen with the same
 * orientation, so their solid angles add. Source: Van Oosterom & Strackee 1983.
 */
export function parallelogramSolidAngle(
  dx: number,
  dy: number,
  dz: number,
  exx: number,
  exy: number,
  exz: number,
  eyx: number,
  eyy: number,
  eyz: number,
): number {
  // Foot F = d + α ex + β ey with (F ⟂ ex, ey): solve the 2×2 Gram system.
  const gxx = exx * exx + exy * exy + exz * exz;
  const gyy = eyx * eyx + eyy * eyy + eyz * eyz;
  const gxy = exx * eyx + exy * eyy + exz * eyz;
  const det = gxx * gyy - gxy * gxy;
  if (!(det > 0)) return 0;
  const rx = -(dx * exx + dy * exy + dz * exz);
  const ry = -(dx * eyx + dy * eyy + dz * eyz);
  const al = (rx * gyy - ry * gxy) / det;
  const be = (ry * gxx - rx * gxy) / det;
  if (al > 0 && al < 1 && be > 0 && be < 1) {
    const fx = dx + al * exx + be * eyx,
      fy = dy + al * exy + be * eyy,
      fz = dz + al * exz + be * eyz;
    // Corner parameters relative to F, counter-clockwise: (0,0), (1,0), (1,1), (0,1).
    const ca = [-al, 1 - al, 1 - al, -al];
    const cb = [-be, -be, 1 - be, 1 - be];
    let sum = 0;
    for (let i = 0; i < 4; i++) {
      const j = (i + 1) & 3;
      const a1 = ca[i],
        b1 = cb[i],
        a2 = ca[j],
        b2 = cb[j];
      sum += triangleSolidAngleEdges(
        fx,
        fy,
        fz,
        a1 * exx + b1 * eyx,
        a1 * exy + b1 * eyy,
        a1 * exz + b1 * eyz,
        a2 * exx + b2 * eyx,
        a2 * exy + b2 * eyy,
        a2 * exz + b2 * eyz,
      );
    }
    return Math.min(sum, 2 * Math.PI);
  }
  const dgx = exx + eyx,
    dgy = exy + eyy,
    dgz = exz + eyz;
  return (
    triangleSolidAngleEdges(dx, dy, dz, exx, exy, exz, dgx, dgy, dgz) +
    triangleSolidAngleEdges(dx, dy, dz, dgx, dgy, dgz, eyx, eyy, eyz)
  );
}

/**
 * Solid angle of a rectangle centred on the axis through the viewpoint, at distance d, with sides
 * w, h: Ω = 4 arcsin(w h / √((w² + 4d²)(h² + 4d²))), evaluated in the equivalent, well-conditioned
 * form Ω = 4 atan(w h / (2d √(w² + h² + 4d²))) (the arcsin form loses half its digits when Ω → 2π).
 * Closed form used as a check and by the scene.
 * Domain: w, h ≥ 0, d > 0 (d = 0 gives 2π for w, h > 0). Measure: steradians.
 * Source: standard result (e.g. R. J. Mathar, "Solid angle of a rectangular plate", 2015).
 */
export function centredRectangleSolidAngle(w: number, h: number, d: number): number {
  if (!(w > 0 && h > 0)) return 0;
  if (d === 0) return 2 * Math.PI;
  const ad = Math.abs(d);
  return 4 * Math.atan((w * h) / (2 * ad * Math.sqrt(w * w + h * h + 4 * ad * ad)));
}

/**
 * The small-patch approximation of exam Q6(a): dω ≈ dA cos θ_l / r², with r the distance from the
 * viewpoint to the patch centre and cos θ_l = |n_l · ω| the cosine between the patch normal and the
 * direction to the viewpoint. Domain: dA ≥ 0, r > 0 (r = 0 → Infinity is avoided: returns 0 for
 * r = 0 or non-finite input). Measure: steradians (exact in the limit dA → 0).
 * Source: pbrt-v4 section 4.2.3 (eq. 4.9), the key's Q6(a).
 */
export function patchSolidAngleApprox(dA: number, cosThetaL: number, r: number): number {
  if (!(r > 0) || !(dA >= 0) || !Number.isFinite(dA) || !Number.isFinite(cosThetaL)) return 0;
  return (dA * Math.abs(cosThetaL)) / (r * r);
}

/**
 * Closed form for an axis-aligned rectangle [x₀, x₁] × [y₀, y₁] in a plane at distance d from the
 * viewpoint (coordinates measured in that plane from the foot of the perpendicular), by
 * inclusion–exclusion of the corner formula F(a, b) = atan(a b / (d √(a² + b² + d²))), the solid angle
 * of [0, a] × [0, b]: Ω = F(x₁, y₁) − F(x₀, y₁) − F(x₁, y₀) + F(x₀, y₀). Domain: x₀ ≤ x₁, y₀ ≤ y₁,
 * d ≠ 0 (sign ignored); d = 0 returns 0. Measure: steradians. Exact, but the four terms cancel
 * for a small distant rectangle — use {@link parallelogramSolidAngle} there. Source: e.g.
 * Mathar 2015, "Solid angle of a rectangular plate"; the corner formula is classical.
 */
export function alignedRectangleSolidAngle(
  x0: number,
  x1: number,
  y0: number,
  y1: number,
  d: number,
): number {
  const ad = Math.abs(d);
  if (!(ad > 0)) return 0;
  const F = (a: number, b: number) => Math.atan((a * b) / (ad * Math.sqrt(a * a + b * b + ad * ad)));
  return Math.abs(F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0));
}
