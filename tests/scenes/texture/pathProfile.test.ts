/**
 * The fast path profile (numeric keys in typed buffers) against the plain one it
 * replaced (string keys over the stencils, kept here as the reference): the same breakpoints, the
 * same samples, the same numbers, bit for bit, over random grids, paths and conventions.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { pathPoint, pathPointInto, type QueryPath } from '../../../src/scenes/texture/path';
import { pathProfile, type CellBorder, type PathProfile } from '../../../src/scenes/texture/pathProfile';
import {
  WRAP_MODES,
  bilinear,
  bilinearStencil,
  bilinearTapsInto,
  checkerGrid,
  examGrid,
  gridRange,
  nearestStencil,
  nearestTapIndex,
  randomGrid,
  type LookupOptions,
  type TextureGrid,
} from '../../../src/core/texture';

// ---- the reference: the plain pathProfile it replaced (string keys, stencil objects) ----
function region(t: number): number {
  return t >= 0 && t <= 1 ? 0 : Math.floor(t);
}

function bilKey(grid: TextureGrid, u: number, v: number, opts: LookupOptions): string {
  const b = bilinearStencil(grid, u, v, opts);
  const vv = opts.vflip ? 1 - v : v;
  return `${b.i0},${b.i1},${b.j0},${b.j1},${region(u)},${region(vv)}`;
}
function nearKey(grid: TextureGrid, u: number, v: number, opts: LookupOptions): string {
  const n = nearestStencil(grid, u, v, opts);
  return `${n.i},${n.j}`;
}

/** All t in (lo, hi] where key changes, each as a bracket [l, h] with h − l ≤ 1e-12 (bisection). */
function findChanges(
  key: (t: number) => string,
  lo: number,
  hi: number,
  kLo: string,
  kHi: string,
  out: [number, number][],
  depth = 0,
): void {
  if (kLo === kHi || depth > 64) return;
  let l = lo;
  let h = hi;
  while (h - l > 1e-12) {
    const m = (l + h) / 2;
    if (m <= l || m >= h) break;
    if (key(m) === kLo) l = m;
    else h = m;
  }
  out.push([l, h]);
  // more than one change inside (lo, hi]: continue from the first one
  if (h < hi) findChanges(key, h, hi, key(h), kHi, out, depth + 1);
}

/**
 * The nearest and bilinear values along the path, sampled at `samples` + 1 evenly spaced t and at
 * both sides of every cell border (found by bisection), with each border classified: a kink where
 * the slope along the path changes, a jump where the value does. Inside one cell bilinear is a
 * smooth function of t (a quadratic along a line), so kinks can only sit at cell borders.
 */
function referenceProfile(
  grid: TextureGrid,
  opts: LookupOptions,
  path: QueryPath,
  samples = 400,
): PathProfile {
  const at = (t: number) => pathPoint(path, t);
  const bilAt = (t: number) => {
    const p = at(t);
    return bilinear(grid, p.u, p.v, opts);
  };
  const bk = (t: number) => {
    const p = at(t);
    return bilKey(grid, p.u, p.v, opts);
  };
  const nk = (t: number) => {
    const p = at(t);
    return nearKey(grid, p.u, p.v, opts);
  };
  const bEvents: [number, number][] = [];
  const nEvents: [number, number][] = [];
  let pb = bk(0);
  let pn = nk(0);
  for (let k = 1; k <= samples; k++) {
    const t0 = (k - 1) / samples;
    const t1 = k / samples;
    const b = bk(t1);
    const n = nk(t1);
    findChanges(bk, t0, t1, pb, b, bEvents);
    findChanges(nk, t0, t1, pn, n, nEvents);
    pb = b;
    pn = n;
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
    const p = at((t0 + t1) / 2);
    const value = nearestStencil(grid, p.u, p.v, opts).value;
    near.push({ t0, t1, value });
    if (value < min) min = value;
    if (value > max) max = value;
  }
  return { ts, bil, breaks, near, borders, nearSwitches: cuts.slice(1, -1), min, max };
}

const OPTS: LookupOptions[] = [];
for (const align of ['corner', 'center'] as const)
  for (const vflip of [false, true]) for (const wrap of WRAP_MODES) OPTS.push({ align, vflip, wrap });

const coord = fc.double({ min: -2.5, max: 3.5, noNaN: true });
const pathArb = fc.record({
  kind: fc.constantFrom<'line' | 'circle'>('line', 'circle'),
  a: fc.tuple(coord, coord),
  b: fc.tuple(coord, coord),
});
const gridArb = fc.oneof(
  fc.constant(examGrid()),
  fc.constant(checkerGrid(8, 8)),
  fc
    .record({
      w: fc.integer({ min: 2, max: 9 }),
      h: fc.integer({ min: 2, max: 9 }),
      seed: fc.integer({ min: 0, max: 1000 }),
    })
    .map(({ w, h, seed }) => randomGrid(w, h, seed)),
);

describe('the path profile, fast form', () => {
  it('equals the reference profile exactly (random grids, paths, conventions)', () => {
    fc.assert(
      fc.property(
        gridArb,
        pathArb,
        fc.constantFrom(...OPTS),
        (grid: TextureGrid, path: QueryPath, opts: LookupOptions) => {
          expect(pathProfile(grid, opts, path, 60)).toEqual(referenceProfile(grid, opts, path, 60));
        },
      ),
      { numRuns: 40, seed: 15 },
    );
  });

  it('equals the reference on the exam, the default path, at full resolution', () => {
    const path: QueryPath = { kind: 'line', a: [0.4, 0.24], b: [0.85, 0.8] };
    for (const opts of OPTS)
      expect(pathProfile(examGrid(), opts, path)).toEqual(referenceProfile(examGrid(), opts, path));
    const circle: QueryPath = { kind: 'circle', a: [0.4, 0.24], b: [1.3, -0.2] };
    expect(pathProfile(checkerGrid(8, 8), OPTS[5], circle)).toEqual(
      referenceProfile(checkerGrid(8, 8), OPTS[5], circle),
    );
  });

  it('pathPointInto gives pathPoint’s numbers; the tap helpers give the stencils’ taps', () => {
    const out = new Float64Array(6);
    fc.assert(
      fc.property(
        gridArb,
        pathArb,
        fc.constantFrom(...OPTS),
        fc.double({ min: -0.5, max: 1.5, noNaN: true }),
        (grid, path, opts, t) => {
          pathPointInto(path, t, out);
          const p = pathPoint(path, t);
          expect([out[0], out[1]]).toEqual([p.u, p.v]);
          bilinearTapsInto(grid, p.u, p.v, opts, out, 1);
          const s = bilinearStencil(grid, p.u, p.v, opts);
          expect([out[1], out[2], out[3], out[4]]).toEqual([s.i0, s.i1, s.j0, s.j1]);
          const n = nearestStencil(grid, p.u, p.v, opts);
          expect(nearestTapIndex(grid, p.u, p.v, opts)).toBe(n.j * grid.width + n.i);
        },
      ),
      { numRuns: 300, seed: 16 },
    );
  });
});
