/**
 * The texel grid's plotted window and its coordinates: the texture frame (u right, v′ up) mapped
 * onto a square SVG viewBox of VB units, shared by the grid's layers and its pointer handling.
 */
import type { LookupOptions, TextureGrid } from '../../../core/texture';

/** viewBox size of the plotted window. */
export const VB = 1000;

export interface ViewWindow {
  min: number;
  max: number;
}

/** The plotted window of (u, v′): [0, 1] with room for texel-centre stencils that cross the edge. */
export function viewWindow(grid: TextureGrid, opts: LookupOptions): ViewWindow {
  const n = Math.min(grid.width, grid.height);
  const m = (opts.align === 'center' ? 0.5 / n : 0) + 0.08;
  return { min: -m, max: 1 + m };
}

/** True when the point lies inside the plotted window. */
export function inWindow(p: { u: number; v: number }, win: ViewWindow): boolean {
  return p.u >= win.min && p.u <= win.max && p.v >= win.min && p.v <= win.max;
}

/** Rounded to four decimals: how a dragged or dialled point is stored. */
export function round4(x: number): number {
  return Math.round(x * 10000) / 10000;
}

/** viewBox x of u. */
export function sx(u: number, win: ViewWindow): number {
  return ((u - win.min) / (win.max - win.min)) * VB;
}
/** viewBox y of v′ (up on the page). */
export function sy(v: number, win: ViewWindow): number {
  return ((win.max - v) / (win.max - win.min)) * VB;
}
