/**
 * The nearest and bilinear values along the query's path, with the places where the bilinear cell
 * changes (found by bisection) and what happens to the value there: a kink, a jump, or nothing.
 */
import {
  bilinear,
  bilinearTapsInto,
  gridRange,
  nearestTapIndex,
  type LookupOptions,
  type TextureGrid,
} from '../../core/texture';
import { pathPointInto, type QueryPath } from './path';

/** A place on the path where the bilinear cell (or the addressing branch) changes. */
export interface CellBorder {
  t: number;
  /** The value jumps there (possible only through addressing, e.g. repeat across the edge). */
  jump: boolean;
  /** The slope along the path changes there (a kink; never inside a cell). */
  kink: boolean;
}

/** The looked-up values along the whole path (for the plot under the grid). */
export interface PathProfile {
  /** Bilinear values as a polyline (t ascending; samples plus both sides of every border). */
  ts: number[];
  bil: number[];
  /** Indices k where the polyline breaks between k − 1 and k (a jump). */
  breaks: number[];
  /** Nearest as a step function: constant pieces [t0, t1). */
  near: { t0: number; t1: number; value: number }[];
  borders: CellBorder[];
  /** Where the nearest node changes (the steps). */
  nearSwitches: number[];
  min: number;
  max: number;
}

/** Which copy of [0, 1] a coordinate is in for addressing: 0 inside (0 and 1 included), else ⌊t⌋. */
function region(t: number): number {
  return t >= 0 && t <= 1 ? 0 : Math.floor(t);
}

/** A place on the path as numbers (which cell, which addressing branch): equal keys, same piece. */
type KeyInto = (t: number, out: Float64Array) => void;

function sameKey(a: Float64Array, b: Float64Array): boolean {
  for (let i = 0; i < a.length; i++) {
    const x = a[i];
    const y = b[i];
    if (x !== y && !(x !== x && y !== y)) return false; // NaN equals NaN, as a key
  }
  return true;
}

/**
 * All t in (lo, hi] where key changes, each as a bracket [l, h] with h − l ≤ 1e-12 (bisection).
 * `scratch` is a key-sized buffer for the probes.
 */
function findChanges(
  key: KeyInto,
  lo: number,
  hi: number,
  kLo: Float64Array,
  kHi: Float64Array,
  out: [number, number][],
  scratch: Float64Array,
  depth = 0,
): void {
  if (sameKey(kLo, kHi) || depth > 64) return;
  let l = lo;
  let h = hi;
  while (h - l > 1e-12) {
    const m = (l + h) / 2;
    if (m <= l || m >= h) break;
    key(m, scratch);
    if (sameKey(scratch, kLo)) l = m;
    else h = m;
  }
  out.push([l, h]);
  // more than one change inside (lo, hi]: continue from the first one
  if (h < hi) {
    const kh = new Float64Array(kLo.length);
    key(h, kh);
    findChanges(key, h, hi, kh, kHi, out, scratch, depth + 1);
  }
}

/**
 * The nearest and bilinear values along the path, sampled at `samples` + 1 evenly spaced t and at
 * both sides of every cell border (found by bisection), with each border classified: a kink where
 * the slope along the path changes, a jump where the value does. Inside one cell bilinear is a
 * smooth function of t (a quadratic along a line), so kinks can only sit at cell borders.
 */
export function pathProfile(
  grid: TextureGrid,
  opts: LookupOptions,
  path: QueryPath,
  samples = 400,
): PathProfile {
  // numbers in typed buffers rather than objects and strings: this runs as the page loads, when
  // the code is still cold, so every allocation and conversion per probe counts
  const pt = new Float64Array(2);
  const bilAt = (t: number) => {
    pathPointInto(path, t, pt);
    return bilinear(grid, pt[0], pt[1], opts);
  };
  /** The bilinear cell (i0, i1, j0, j1) and which copy of [0, 1] u and v′ are in (0 inside, else ⌊t⌋). */
  const bk: KeyInto = (t, out) => {
    pathPointInto(path, t, pt);
    const u = pt[0];
    const v = pt[1];
    bilinearTapsInto(grid, u, v, opts, out);
    const vv = opts.vflip ? 1 - v : v;
    out[4] = region(u);
    out[5] = region(vv);
  };
  /** The nearest node. */
  const nk: KeyInto = (t, out) => {
    pathPointInto(path, t, pt);
    out[0] = nearestTapIndex(grid, pt[0], pt[1], opts);
  };
  const bEvents: [number, number][] = [];
  const nEvents: [number, number][] = [];
  let pb = new Float64Array(6);
  let b = new Float64Array(6);
  let pn = new Float64Array(1);
  let n = new Float64Array(1);
  const bScratch = new Float64Array(6);
  const nScratch = new Float64Array(1);
  bk(0, pb);
  nk(0, pn);
  for (let k = 1; k <= samples; k++) {
    const t0 = (k - 1) / samples;
    const t1 = k / samples;
    bk(t1, b);
    nk(t1, n);
    findChanges(bk, t0, t1, pb, b, bEvents, bScratch);
    findChanges(nk, t0, t1, pn, n, nEvents, nScratch);
    [pb, b] = [b, pb];
    [pn, n] = [n, pn];
  }
  const range = gridRange(grid);
  const scale = Math.max(1, Math.abs(range.max), Math.abs(range.min), range.max - range.min);
  const borders: CellBorder[] = bEvents.map(([l, r], i) => {
    const fl = bilAt(l);
    const fr = bilAt(r);
    const jump = Math.abs(fl - fr) > 1e-9 * scale;
    // room on each side before the neighbouring border, so the slopes are taken inside one cell
    const roomL = l - (i > 0 ? bEvents[i - 1][1] : 0);
    const roomR = (i + 1 < bEvents.length ? bEvents[i + 1][0] : 1) - r;
    const h = Math.min(1e-4, roomL / 3, roomR / 3);
    let kink = false;
    if (!jump && h > 1e-9) {
      // second-order one-sided slopes (exact for the quadratic a line traces inside a cell)
      const sl = (3 * fl - 4 * bilAt(l - h) + bilAt(l - 2 * h)) / (2 * h);
      const sr = (-3 * fr + 4 * bilAt(r + h) - bilAt(r + 2 * h)) / (2 * h);
      kink = Math.abs(sl - sr) > 1e-6 * scale;
    }
    return { t: (l + r) / 2, jump, kink };
  });
  // bilinear polyline: samples plus both sides of each border
  const pts: { t: number; brk: boolean }[] = [];
  for (let k = 0; k <= samples; k++) pts.push({ t: k / samples, brk: false });
  bEvents.forEach(([l, r], i) => {
    pts.push({ t: l, brk: false });
    pts.push({ t: r, brk: borders[i].jump });
  });
  pts.sort((x, y) => x.t - y.t);
  const ts: number[] = [];
  const bil: number[] = [];
  const breaks: number[] = [];
  let min = Infinity;
  let max = -Infinity;
  for (const p of pts) {
    if (ts.length && p.t === ts[ts.length - 1]) continue;
    if (p.brk) breaks.push(ts.length);
    const y = bilAt(p.t);
    ts.push(p.t);
    bil.push(y);
    if (y < min) min = y;
    if (y > max) max = y;
  }
  // nearest: constant between switches
  const cuts = [0, ...nEvents.map(([l, r]) => (l + r) / 2), 1];
  const near: PathProfile['near'] = [];
  for (let k = 0; k + 1 < cuts.length; k++) {
    const t0 = cuts[k];
    const t1 = cuts[k + 1];
    pathPointInto(path, (t0 + t1) / 2, pt);
    const value = grid.values[nearestTapIndex(grid, pt[0], pt[1], opts)];
    near.push({ t0, t1, value });
    if (value < min) min = value;
    if (value > max) max = value;
  }
  return { ts, bil, breaks, near, borders, nearSwitches: cuts.slice(1, -1), min, max };
}
