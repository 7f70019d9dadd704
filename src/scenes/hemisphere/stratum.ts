/**
 * One stratum of the unit square followed onto the hemisphere (the Nori warp-test view): a cell
 * (i, j) of the 8 × 8 grid of (ξ₁, ξ₂), its outline and a patch mesh in the square and on the
 * hemisphere (the view mixes the two by the morph fraction, as it does the grid), the patch's
 * solid angle and how dense the samples are there. Pure functions, no DOM.
 */
import { fillSequence2D, type SequenceKind } from '../../core/random';
import { TWO_PI, sphericalPhi, sphericalTheta } from '../../core/sampling';
import { GRID_LINES, squarePoint } from './animation';
import type { Lobe } from './lobe';

/** A cell of the square: ξ₁ ∈ [i/8, (i + 1)/8) (column i), ξ₂ ∈ [j/8, (j + 1)/8) (row j). */
export interface Cell {
  i: number;
  j: number;
}

/** Cells per side of the square (the warped grid's strata). */
export const CELLS = GRID_LINES;

/**
 * The cell the URL asks for (`cell=i,j`, the shell has clamped each to [0, 7] and said so): null
 * when none; a fractional index is rounded, with a sentence saying so.
 */
export function cellFromParam(v: readonly number[] | null): { cell: Cell | null; problem: string | null } {
  if (!v || v.length !== 2) return { cell: null, problem: null };
  const [a, b] = v;
  const i = Math.min(CELLS - 1, Math.max(0, Math.round(a)));
  const j = Math.min(CELLS - 1, Math.max(0, Math.round(b)));
  const problem =
    i !== a || j !== b
      ? `cell=${a},${b} is not two whole numbers from 0 to ${CELLS - 1}; following cell (${i}, ${j})`
      : null;
  return { cell: { i, j }, problem };
}

/** The ξ ranges of a cell: [lo, hi) in each coordinate. */
export function cellBounds(c: Cell): { xi1: [number, number]; xi2: [number, number] } {
  return { xi1: [c.i / CELLS, (c.i + 1) / CELLS], xi2: [c.j / CELLS, (c.j + 1) / CELLS] };
}

/** The cell that holds (ξ₁, ξ₂) ∈ [0, 1)². */
export function cellOf(xi1: number, xi2: number): Cell {
  const k = (x: number) => Math.min(CELLS - 1, Math.max(0, Math.floor(x * CELLS)));
  return { i: k(xi1), j: k(xi2) };
}

/** The cell one step away (arrow keys), kept inside the square. */
export function stepCell(c: Cell, di: number, dj: number): Cell {
  const k = (x: number) => Math.min(CELLS - 1, Math.max(0, x));
  return { i: k(c.i + di), j: k(c.j + dj) };
}

// the sampler's input stays below 1 (the lobes' inversions are defined on [0, 1))
const TOP = 1 - 2 ** -53;

/** Where (ξ₁, ξ₂) goes on the hemisphere, written to out[o..o+2]. */
function warp(lobe: Lobe, a: number, b: number, out: Float64Array, o: number): void {
  lobe.sample(Math.min(a, TOP), Math.min(b, TOP), out, o);
}

/**
 * The cell's outline as a closed loop, `perEdge` pieces on each side (ξ₁ rising along the bottom,
 * then ξ₂ rising on the right, …): 4·perEdge vertices of 3 numbers in the square (s = 0, `a`) and
 * on the hemisphere (s = 1, `b`). The vertices at morph s are `morphPoint(a, b, s)`.
 */
export function cellOutline(lobe: Lobe, c: Cell, perEdge = 24): { a: Float64Array; b: Float64Array } {
  const { xi1, xi2 } = cellBounds(c);
  const corners = [
    [xi1[0], xi2[0]],
    [xi1[1], xi2[0]],
    [xi1[1], xi2[1]],
    [xi1[0], xi2[1]],
  ];
  const m = 4 * perEdge;
  const a = new Float64Array(3 * m);
  const b = new Float64Array(3 * m);
  for (let q = 0; q < m; q++) {
    const side = Math.floor(q / perEdge);
    const f = (q % perEdge) / perEdge;
    const [u0, v0] = corners[side];
    const [u1, v1] = corners[(side + 1) % 4];
    const u = u0 + f * (u1 - u0);
    const v = v0 + f * (v1 - v0);
    squarePoint(u, v, a, 3 * q);
    warp(lobe, u, v, b, 3 * q);
  }
  return { a, b };
}

/**
 * The cell as a mesh: a (sub + 1)² grid of vertices in the square (`a`) and on the hemisphere
 * (`b`), and two triangles per sub-square (`index`).
 */
export function cellPatch(
  lobe: Lobe,
  c: Cell,
  sub = 12,
): { a: Float64Array; b: Float64Array; index: Uint16Array } {
  const { xi1, xi2 } = cellBounds(c);
  const side = sub + 1;
  const a = new Float64Array(3 * side * side);
  const b = new Float64Array(3 * side * side);
  for (let r = 0; r <= sub; r++) {
    for (let q = 0; q <= sub; q++) {
      const u = xi1[0] + ((xi1[1] - xi1[0]) * q) / sub;
      const v = xi2[0] + ((xi2[1] - xi2[0]) * r) / sub;
      const k = 3 * (r * side + q);
      squarePoint(u, v, a, k);
      warp(lobe, u, v, b, k);
    }
  }
  const index = new Uint16Array(6 * sub * sub);
  let t = 0;
  for (let r = 0; r < sub; r++) {
    for (let q = 0; q < sub; q++) {
      const v0 = r * side + q;
      index.set([v0, v0 + 1, v0 + side + 1, v0, v0 + side + 1, v0 + side], t);
      t += 6;
    }
  }
  return { a, b, index };
}

/** Morph vertices from `a` (s = 0) to `b` (s = 1) into `out`: the model's morphPoint, element by element. */
export function morphVertices(a: Float64Array, b: Float64Array, s: number, out: Float32Array): void {
  const r = 1 - s;
  for (let k = 0; k < a.length; k++) out[k] = a[k] * r + b[k] * s;
}

/** Solid angle of the geodesic triangle (u, v, w) on the unit sphere (Van Oosterom and Strackee, 1983). */
function triangleSolidAngle(p: Float64Array, i: number, j: number, k: number): number {
  const ax = p[i],
    ay = p[i + 1],
    az = p[i + 2];
  const bx = p[j],
    by = p[j + 1],
    bz = p[j + 2];
  const cx = p[k],
    cy = p[k + 1],
    cz = p[k + 2];
  const triple = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  const den = 1 + ax * bx + ay * by + az * bz + bx * cx + by * cy + bz * cz + cx * ax + cy * ay + cz * az;
  return Math.abs(2 * Math.atan2(triple, den));
}

/** What a cell becomes on the hemisphere. */
export interface CellImage {
  /** Range of θ over the patch (rad). */
  theta: [number, number];
  /** Range of φ over the patch (rad, in [0, 2π)); `phiWraps` when it runs across φ = 0. */
  phi: [number, number];
  phiWraps: boolean;
  /** The patch reaches the pole (θ = 0), where φ is undefined. */
  pole: boolean;
  /** Solid angle of the patch (sr). */
  solidAngle: number;
  /** The patch's share of the hemisphere's 2π sr. */
  share: number;
  /**
   * Average sample density over the patch relative to uniform sampling: every cell holds 1/64 of
   * the probability, so this is (1/64)/(Ω/2π).
   */
  densityRatio: number;
  /** True when the patch's area is approximate (a tabulated sampler tears cells along its rows). */
  approximate: boolean;
}

/** The patch a cell lands on: θ and φ ranges, its solid angle (from a fine mesh of the cell) and the sample density there. */
export function cellImage(lobe: Lobe, c: Cell, sub = 24): CellImage {
  const { b, index } = cellPatch(lobe, c, sub);
  let omega = 0;
  for (let t = 0; t < index.length; t += 3) {
    omega += triangleSolidAngle(b, 3 * index[t], 3 * index[t + 1], 3 * index[t + 2]);
  }
  // φ unwrapped about the centre of the cell's image, so a patch across φ = 0 has one range
  const centre = new Float64Array(3);
  const { xi1, xi2 } = cellBounds(c);
  warp(lobe, (xi1[0] + xi1[1]) / 2, (xi2[0] + xi2[1]) / 2, centre, 0);
  const phiC = sphericalPhi(centre[0], centre[1]);
  let tMin = Infinity,
    tMax = -Infinity,
    dMin = Infinity,
    dMax = -Infinity;
  let pole = false;
  for (let k = 0; k < b.length; k += 3) {
    const th = sphericalTheta(b[k], b[k + 1], b[k + 2]);
    tMin = Math.min(tMin, th);
    tMax = Math.max(tMax, th);
    if (th < 1e-6) {
      pole = true;
      continue; // φ is undefined at the pole
    }
    let d = sphericalPhi(b[k], b[k + 1]) - phiC;
    if (d > Math.PI) d -= TWO_PI;
    if (d <= -Math.PI) d += TWO_PI;
    dMin = Math.min(dMin, d);
    dMax = Math.max(dMax, d);
  }
  const wrap = (x: number) => ((x % TWO_PI) + TWO_PI) % TWO_PI;
  const lo = wrap(phiC + dMin);
  // the top edge of a cell in the last row reaches φ = 2π itself
  const hiRaw = phiC + dMax;
  const hi = hiRaw >= TWO_PI - 1e-9 && hiRaw <= TWO_PI + 1e-9 ? TWO_PI : wrap(hiRaw);
  const share = omega / TWO_PI;
  return {
    theta: [tMin, tMax],
    phi: [lo, hi],
    phiWraps: hi < lo,
    pole,
    solidAngle: omega,
    share,
    densityRatio: share > 0 ? 1 / (CELLS * CELLS) / share : Infinity,
    approximate: lobe.id === 'custom',
  };
}

/**
 * How many of the first n points of the set lie in the cell, counted over points [from, to) in
 * batches (the caller sums slices to keep each task short).
 */
export function countInCell(
  kind: SequenceKind,
  seed: number,
  n: number,
  c: Cell,
  from: number,
  to: number,
  scratch: Float64Array,
): number {
  const batch = scratch.length >> 1;
  const { xi1, xi2 } = cellBounds(c);
  let count = 0;
  for (let s = from; s < to; s += batch) {
    const e = Math.min(to, s + batch);
    fillSequence2D(kind, seed, n, scratch, s, e, 0);
    for (let k = 0; k < 2 * (e - s); k += 2) {
      const a = scratch[k];
      const b = scratch[k + 1];
      if (a >= xi1[0] && a < xi1[1] && b >= xi2[0] && b < xi2[1]) count++;
    }
  }
  return count;
}

/** How many of the first `count` points of the set fall in each cell (index j·8 + i). */
export function cellCounts(kind: SequenceKind, seed: number, n: number, count: number): Uint32Array {
  const out = new Uint32Array(CELLS * CELLS);
  const u = new Float64Array(2 * Math.min(count, n));
  fillSequence2D(kind, seed, n, u, 0, Math.min(count, n), 0);
  for (let k = 0; k < u.length; k += 2) {
    const c = cellOf(u[k], u[k + 1]);
    out[c.j * CELLS + c.i]++;
  }
  return out;
}
