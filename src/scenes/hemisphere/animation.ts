/**
 * The scene's animation, a pure function of (params, seed, t): the warp morph from the unit square
 * to the hemisphere and the growth of the sample cloud, with the warped (ξ₁, ξ₂) grid.
 */
import { sphericalPhi, sphericalTheta } from '../../core/sampling';
import { fillSequence2D, type SequenceKind } from '../../core/random';
import type { Lobe } from './lobe';

/** Which animation the shared timeline plays: the warp morph (square → hemisphere) or the growth. */
export type AnimKind = 'warp' | 'grow';

/** Seconds from t = 0 to t = 1 at 1× speed. Growth keeps its old pace: 0.7 s per decade of N. */
export function animDuration(anim: AnimKind, n: number): number {
  return anim === 'warp' ? 4 : Math.max(1.5, 0.7 * Math.log10(Math.max(10, n)));
}

/** Growth: how many of the n samples are on screen at position t ∈ [0, 1] (geometric, 0 at t = 0, n at t = 1). */
export function growCount(n: number, t: number): number {
  if (!(t > 0) || n <= 0) return 0;
  if (t >= 1) return n;
  return Math.min(n, Math.max(1, Math.round(Math.pow(n, t))));
}

/** Warp morph: the eased fraction s(t) = t²(3 − 2t) of the way from the square to the hemisphere. */
export function morphFraction(t: number): number {
  const c = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0));
  return c * c * (3 - 2 * c);
}

/**
 * Where the point (ξ₁, ξ₂) sits in the unit square as drawn in 3D: the square [−1, 1]² in the base
 * plane z = 0, ξ₁ along +x and ξ₂ along +y (so it frames the hemisphere's base disk).
 */
export function squarePoint(
  xi1: number,
  xi2: number,
  out: number[] | Float64Array = [0, 0, 0],
  o = 0,
): number[] | Float64Array {
  out[o] = 2 * xi1 - 1;
  out[o + 1] = 2 * xi2 - 1;
  out[o + 2] = 0;
  return out;
}

/** The morphed position: (1 − s)·square + s·direction (the view's shader evaluates the same mix). */
export function morphPoint(
  sq: ArrayLike<number>,
  dir: ArrayLike<number>,
  s: number,
  out: number[] | Float64Array = [0, 0, 0],
  o = 0,
  so = 0,
  dOff = 0,
): number[] | Float64Array {
  // GLSL's mix(x, y, s) = x(1 − s) + y s: exactly the square at s = 0 and the direction at s = 1
  const r = 1 - s;
  out[o] = sq[so] * r + dir[dOff] * s;
  out[o + 1] = sq[so + 1] * r + dir[dOff + 1] * s;
  out[o + 2] = sq[so + 2] * r + dir[dOff + 2] * s;
  return out;
}

/** Number of grid lines per axis of the warped (ξ₁, ξ₂) grid (8 strata of each ξ). */
export const GRID_LINES = 8;

/** What the animation shows at position t (readouts the view prints and the tests recompute). */
export interface AnimFrame {
  anim: AnimKind;
  /** Samples drawn (growth) or morphed (warp). */
  shown: number;
  /** Morph fraction s (1 for the growth animation: points sit on the hemisphere). */
  s: number;
  /** The tracked sample: the first of the set, its (ξ₁, ξ₂), its direction and where it is now. */
  tracked: {
    xi1: number;
    xi2: number;
    theta: number;
    phi: number;
    dir: [number, number, number];
    pos: [number, number, number];
  } | null;
}

/** The animation frame for (lobe, point set, seed, n) at position t. */
export function animFrame(
  lobe: Lobe | null,
  kind: SequenceKind,
  seed: number,
  n: number,
  anim: AnimKind,
  t: number,
): AnimFrame {
  const s = anim === 'warp' ? morphFraction(t) : 1;
  const shown = !lobe ? 0 : anim === 'warp' ? n : growCount(n, t);
  let tracked: AnimFrame['tracked'] = null;
  if (lobe && n > 0 && shown > 0) {
    const u = new Float64Array(2);
    fillSequence2D(kind, seed, n, u, 0, 1, 0);
    const d = new Float64Array(3);
    lobe.sampleBatch(u, d, 1);
    const sq = squarePoint(u[0], u[1]);
    const p = morphPoint(sq, d, s);
    tracked = {
      xi1: u[0],
      xi2: u[1],
      theta: sphericalTheta(d[0], d[1], d[2]),
      phi: sphericalPhi(d[0], d[1]),
      dir: [d[0], d[1], d[2]],
      pos: [p[0], p[1], p[2]],
    };
  }
  return { anim, shown, s, tracked };
}

/**
 * The warped grid at morph fraction s: line segments (pairs of points, 3 numbers each) of the
 * GRID_LINES + 1 lines of constant ξ₁ and of constant ξ₂, `segments` pieces each, morphed from
 * the square to the lobe's image. `xi` receives the (ξ₁, ξ₂) of each vertex (for colours).
 */
export function warpedGrid(lobe: Lobe, s: number, segments = 48): { pos: Float64Array; xi: Float64Array } {
  const verts = 2 * 2 * (GRID_LINES + 1) * segments;
  const pos = new Float64Array(3 * verts);
  const xi = new Float64Array(2 * verts);
  const d = [0, 0, 0];
  const sq = [0, 0, 0];
  let k = 0;
  const top = 1 - 2 ** -53;
  const put = (a: number, b: number) => {
    lobe.sample(Math.min(a, top), Math.min(b, top), d, 0);
    squarePoint(a, b, sq);
    morphPoint(sq, d, s, pos, 3 * k);
    xi[2 * k] = a;
    xi[2 * k + 1] = b;
    k++;
  };
  for (let l = 0; l <= GRID_LINES; l++) {
    const fixed = l / GRID_LINES;
    for (let q = 0; q < segments; q++) {
      const t0 = q / segments;
      const t1 = (q + 1) / segments;
      put(fixed, t0);
      put(fixed, t1);
      put(t0, fixed);
      put(t1, fixed);
    }
  }
  return { pos, xi };
}
