/**
 * The 2D cross-section through the ray and the sphere's centre: the canonical in-plane frame, the
 * line's closest approach to the centre, and conversions between world and frame coordinates.
 */
import { cross, dot, norm, scale, sub, type Vec3 } from '../../core/vec3';

export interface Frame2D {
  /** Anchor (the centre at the time the frame was made) and orthonormal in-plane axes. */
  p: Vec3;
  e1: Vec3;
  e2: Vec3;
}

/**
 * l = f − (f·d / d·d) d with f = o − C: from the centre to the closest point of the ray's line
 * (the vector of the robust form); |l| is the line's distance from the centre.
 */
export function closestOffset(o: Vec3, d: Vec3, c: Vec3): Vec3 {
  const f = sub(o, c);
  return sub(f, scale(d, dot(f, d) / dot(d, d)));
}

/** The distance of the ray's line from the centre: the closest approach (tangent when it is r). */
export const closestApproach = (o: Vec3, d: Vec3, c: Vec3) => norm(closestOffset(o, d, c));

/**
 * The canonical frame: e1 along d, e2 from the centre towards the ray's line (the ray then runs
 * horizontally above the centre), anchored at the centre. If the centre is on the line, e2 is the
 * in-plane direction closest to world z (or y).
 */
export function canonicalFrame(o: Vec3, d: Vec3, c: Vec3): Frame2D {
  const e1 = scale(d, 1 / norm(d));
  const f = sub(o, c);
  const l = sub(f, scale(e1, dot(f, e1)));
  const ln = norm(l);
  let e2: Vec3;
  if (ln > 1e-12 * (norm(f) + 1e-300)) e2 = scale(l, 1 / ln);
  else {
    const up: Vec3 = Math.abs(e1[2]) < 0.9 ? [0, 0, 1] : [0, 1, 0];
    const w = sub(up, scale(e1, dot(up, e1)));
    e2 = scale(w, 1 / norm(w));
  }
  return { p: [c[0], c[1], c[2]], e1, e2 };
}

/** Is the ray's line and the centre (still) in the frame's plane, to a tolerance `tol` in length? */
export function frameFits(fr: Frame2D, o: Vec3, d: Vec3, c: Vec3, tol: number): boolean {
  const n = cross(fr.e1, fr.e2);
  const dn = Math.abs(dot(d, n)) / norm(d);
  return Math.abs(dot(sub(o, fr.p), n)) <= tol && Math.abs(dot(sub(c, fr.p), n)) <= tol && dn <= 1e-9;
}

/** World → frame coordinates (x along e1, y along e2). */
export function toFrame(fr: Frame2D, q: Vec3): [number, number] {
  const v = sub(q, fr.p);
  return [dot(v, fr.e1), dot(v, fr.e2)];
}

/** Frame → world coordinates. */
export function fromFrame(fr: Frame2D, x: number, y: number): Vec3 {
  return [
    fr.p[0] + x * fr.e1[0] + y * fr.e2[0],
    fr.p[1] + x * fr.e1[1] + y * fr.e2[1],
    fr.p[2] + x * fr.e1[2] + y * fr.e2[2],
  ];
}

/** In-plane direction → world direction. */
export function dirFromFrame(fr: Frame2D, x: number, y: number): Vec3 {
  return [x * fr.e1[0] + y * fr.e2[0], x * fr.e1[1] + y * fr.e2[1], x * fr.e1[2] + y * fr.e2[2]];
}
