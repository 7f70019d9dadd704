/**
 * The animation of the texture scene: the query point travels a path, and everything on screen at
 * position t is a function of the parameters and t computed here.
 */
import type { LookupOptions, TextureGrid } from '../../core/texture';
import { lookupAt, type Lookup, type TextureParams } from './model';
import type { PathKind } from './params';

/** The query's path: a line from a to b, or the circle with a and b as the ends of a diameter. */
export interface QueryPath {
  kind: PathKind;
  a: readonly [number, number];
  b: readonly [number, number];
}

export function pathOf(p: Pick<TextureParams, 'u' | 'v' | 'u2' | 'v2' | 'path'>): QueryPath {
  return { kind: p.path === 'circle' ? 'circle' : 'line', a: [p.u, p.v], b: [p.u2, p.v2] };
}

/**
 * The query (u, v) at position t ∈ [0, 1] of the path (t outside is clamped; NaN → 0). Line:
 * a + t (b − a), at constant speed. Circle: starts at a, runs once counter-clockwise (u right, v
 * up) round the centre (a + b)/2 at constant speed and is back at a for t = 1. t = 0 gives a
 * exactly (so the opening state is the exam's query), and t = 1 gives b (line) or a (circle).
 */
export function pathPoint(path: QueryPath, t: number): { u: number; v: number } {
  const s = Number.isFinite(t) ? Math.min(1, Math.max(0, t)) : 0;
  const [au, av] = path.a;
  const [bu, bv] = path.b;
  if (s === 0) return { u: au, v: av };
  if (path.kind === 'line') {
    if (s === 1) return { u: bu, v: bv };
    return { u: au + s * (bu - au), v: av + s * (bv - av) };
  }
  if (s === 1) return { u: au, v: av };
  const cu = (au + bu) / 2;
  const cv = (av + bv) / 2;
  const r = Math.hypot(au - cu, av - cv);
  const a0 = Math.atan2(av - cv, au - cu);
  const ang = a0 + 2 * Math.PI * s;
  return { u: cu + r * Math.cos(ang), v: cv + r * Math.sin(ang) };
}

/** {@link pathPoint} written to out[0] (u) and out[1] (v) instead of a new object: the same arithmetic, the same numbers. */
export function pathPointInto(path: QueryPath, t: number, out: Float64Array): void {
  const s = Number.isFinite(t) ? Math.min(1, Math.max(0, t)) : 0;
  const [au, av] = path.a;
  const [bu, bv] = path.b;
  if (s === 0 || (s === 1 && path.kind !== 'line')) {
    out[0] = au;
    out[1] = av;
  } else if (path.kind === 'line') {
    out[0] = s === 1 ? bu : au + s * (bu - au);
    out[1] = s === 1 ? bv : av + s * (bv - av);
  } else {
    const cu = (au + bu) / 2;
    const cv = (av + bv) / 2;
    const r = Math.hypot(au - cu, av - cv);
    const a0 = Math.atan2(av - cv, au - cu);
    const ang = a0 + 2 * Math.PI * s;
    out[0] = cu + r * Math.cos(ang);
    out[1] = cv + r * Math.sin(ang);
  }
}

/** Everything the animated part of the scene shows at position t (a pure function of its inputs). */
export interface Frame {
  t: number;
  u: number;
  v: number;
  lookup: Lookup;
}

export function frameAt(grid: TextureGrid, opts: LookupOptions, path: QueryPath, t: number): Frame {
  const p = pathPoint(path, t);
  return { t, u: p.u, v: p.v, lookup: lookupAt(grid, p.u, p.v, opts) };
}
