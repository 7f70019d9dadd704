/**
 * The settings of a texture lookup on a texel grid and where they put the nodes: the two
 * node conventions, the v-flip and the wrap mode, shared by nearest (./nearest.ts), bilinear
 * (./bilinear.ts) and the whole-image reconstruction (./reconstruct.ts).
 *
 * Conventions (per axis; N = width for u, N = height for v):
 * - `corner` (the exam's): node i sits at i / (N − 1), so the nodes cover [0, 1] exactly and the
 *   cell size is 1 / (N − 1). The coordinate is first addressed into [0, 1] ({@link addressCoord}).
 * - `center` (the GPU's): texel i is the cell [i/N, (i+1)/N] and its value sits at its centre
 *   (i + ½) / N; the cell size is 1 / N. Taps are addressed per index ({@link addressIndex}), as in
 *   OpenGL (spec §8.14.2), so under repeat a stencil can mix the last and the first texel.
 * - `vflip`: the key's alternative reading v' = 1 − v is applied before anything else.
 *
 * Ties in nearest (a query exactly half-way between two nodes) go to the larger index
 * (corner: Math.round; center: ⌊u N⌋, which is the texel whose half-open cell [i/N, (i+1)/N) holds u).
 *
 * Sources: pbrt-v4 §10.4.3 (Image::Bilerp, texel centres at (i + ½)/N); OpenGL 4.6 spec §8.14.2
 * (nearest: ⌊u N⌋; linear: i0 = ⌊u N − ½⌋, α = frac(u N − ½)); the exam's Q3 for the corner form.
 */
import { addressCoord, type WrapMode } from './addressing';

/** Where the nodes sit. */
export type Align = 'corner' | 'center';

/** The lookup settings a scene exposes. */
export interface LookupOptions {
  align: Align;
  /** Use v' = 1 − v (the key accepts this reading of the grid). */
  vflip: boolean;
  wrap: WrapMode;
}

/** The exam's settings: corner-aligned nodes, no flip, clamp. */
export const EXAM_LOOKUP: LookupOptions = { align: 'corner', vflip: false, wrap: 'clamp' };

/** Continuous position of a query along one axis, shared by nearest and bilinear. */
export interface AxisPos {
  /** The coordinate as used: after the flip and, for corner nodes, after addressing. */
  t: number;
  /** Texel-space position: t (N − 1) for corner nodes, t N − ½ for centres. */
  s: number;
}

/** Where a query's coordinate t sits along an axis of n nodes (after the flip, before the taps). */
export function axisPos(t: number, n: number, align: Align, wrap: WrapMode): AxisPos {
  if (align === 'corner') {
    const a = addressCoord(t, wrap);
    return { t: a, s: a * (n - 1) };
  }
  const tt = Number.isFinite(t) ? t : 0;
  return { t: tt, s: tt * n - 0.5 };
}

/** Node coordinate of (unaddressed) index k along an axis of n nodes. */
export function nodeCoord(k: number, n: number, align: Align): number {
  return align === 'corner' ? k / (n - 1) : (k + 0.5) / n;
}

/** Cell size along an axis of n nodes: 1/(n − 1) for corner nodes, 1/n for centres. */
export function cellSize(n: number, align: Align): number {
  return align === 'corner' ? 1 / (n - 1) : 1 / n;
}

/** v as the lookup reads it: 1 − v under the v-flip. */
export function flipV(v: number, vflip: boolean): number {
  return vflip ? 1 - v : v;
}
