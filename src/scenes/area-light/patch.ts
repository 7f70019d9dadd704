/**
 * Q6(a) in numbers: a small square patch on the light, its exact solid angle seen from the shading
 * point (Van Oosterom–Strackee) against dA cos θ_l / r², and how their difference shrinks with the
 * patch. Pure functions of the model.
 */
import { makeRectLight, type RectLight, type Vec3 } from '../../core/lights';
import { patchSolidAngleApprox, parallelogramSolidAngle } from '../../core/geometry/solidAngle';
import type { AreaLightModel } from './model';

export interface PatchModel {
  /** Patch corners (world), counter-clockwise. */
  corners: Vec3[];
  centre: Vec3;
  /** Unit normal of the patch (emitting side of the light, tilted by ptilt). */
  normal: Vec3;
  side: number;
  area: number;
  r: number;
  cosThetaL: number;
  exact: number;
  approx: number;
  /** (approx − exact)/exact. */
  relError: number;
  /** Corners projected onto the unit sphere around p (world positions). */
  projected: Vec3[];
  /** Relative error against side length as the patch shrinks (for the plot). */
  series: { side: Float64Array; relError: Float64Array };
}

/** A square patch of side s at (pu, pv) on the light, tilted by ptilt about the light's x axis. */
export function patchGeometry(m: AreaLightModel, pu: number, pv: number, side: number, ptilt: number) {
  const { corner, edgeX, edgeY } = m.light;
  const at = (k: number) => corner[k] + pu * edgeX[k] + pv * edgeY[k];
  return makeRectLight([at(0), at(1), at(2)], side, side, m.tilt + ptilt);
}

export function patchModel(
  m: AreaLightModel,
  pu: number,
  pv: number,
  side: number,
  ptilt: number,
): PatchModel {
  const patch = patchGeometry(m, pu, pv, side, ptilt);
  const [px, py, pz] = m.p;
  const c = patch.center;
  const measure = (pt: RectLight) => {
    const dx = pt.center[0] - px,
      dy = pt.center[1] - py,
      dz = pt.center[2] - pz;
    const r = Math.hypot(dx, dy, dz);
    const cosL = r > 0 ? Math.abs(dx * pt.normal[0] + dy * pt.normal[1] + dz * pt.normal[2]) / r : 0;
    const exact = parallelogramSolidAngle(
      pt.corner[0] - px,
      pt.corner[1] - py,
      pt.corner[2] - pz,
      ...pt.edgeX,
      ...pt.edgeY,
    );
    const approx = patchSolidAngleApprox(pt.area, cosL, r);
    return { r, cosL, exact, approx, rel: exact > 0 ? (approx - exact) / exact : NaN };
  };
  const cur = measure(patch);
  const projected = patch.corners.map((q): Vec3 => {
    const d = [q[0] - px, q[1] - py, q[2] - pz];
    const len = Math.hypot(d[0], d[1], d[2]) || 1;
    return [px + d[0] / len, py + d[1] / len, pz + d[2] / len];
  });
  const K = 25;
  const sides = new Float64Array(K);
  const rels = new Float64Array(K);
  const sMax = Math.max(side, 1);
  for (let i = 0; i < K; i++) {
    const s = sMax * 10 ** (-(5 * i) / (K - 1));
    sides[i] = s;
    const r = measure(makeRectLight(c, s, s, m.tilt + ptilt)).rel;
    rels[i] = Number.isFinite(r) ? Math.abs(r) : NaN;
  }
  return {
    corners: patch.corners,
    centre: c,
    normal: patch.normal,
    side,
    area: patch.area,
    r: cur.r,
    cosThetaL: cur.cosL,
    exact: cur.exact,
    approx: cur.approx,
    relError: cur.rel,
    projected,
    series: { side: sides, relError: rels },
  };
}
