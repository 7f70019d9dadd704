/**
 * A worker's share of a progressive render, as plain data in and out: one tile of the image,
 * rendered pass after pass (each pass `passSpp` samples per pixel, up to `spp` in all), handing
 * each pass's running sums to a callback (which may await, so a worker can post progress and
 * yield between passes). The tile's sums and counts are pixel for pixel those the whole-image
 * renderer would produce, so the page merges tiles from several workers by copying rows.
 */
import { makeCpuRenderer, newAccumulation, renderTilePass, type Tile } from './cpuRenderer';
import type { TraceOptions } from './pathTrace';
import { buildScene, type RenderSpec, type View } from './scene';

export interface TileJobArgs extends TraceOptions {
  spec: RenderSpec;
  view: View;
  width: number;
  height: number;
  tile: Tile;
  seed: number;
  /** Samples per pixel in all, and per pass. */
  spp: number;
  passSpp: number;
}

/** A tile's progress: its sums and sample counts (tile-sized, row-major), passes done and paths traced. */
export interface TileResult {
  tile: Tile;
  sum: Float64Array;
  count: Uint32Array;
  passes: number;
  spp: number;
  paths: number;
}

/** Copy the tile's part of a full-size accumulation into tile-sized arrays. */
function tileOf(
  tile: Tile,
  width: number,
  sum: Float64Array,
  count: Uint32Array,
): { sum: Float64Array; count: Uint32Array } {
  const s = new Float64Array(tile.w * tile.h);
  const c = new Uint32Array(tile.w * tile.h);
  for (let y = 0; y < tile.h; y++) {
    const from = (tile.y0 + y) * width + tile.x0;
    s.set(sum.subarray(from, from + tile.w), y * tile.w);
    c.set(count.subarray(from, from + tile.w), y * tile.w);
  }
  return { sum: s, count: c };
}

/**
 * Render the tile progressively; `onPass` receives a fresh copy after every pass. Returns the
 * final state. Passes are numbered from 0, so a tile's samples do not depend on the split.
 */
export async function renderTileJob(
  a: TileJobArgs,
  onPass?: (r: TileResult, fraction: number) => void | Promise<void>,
): Promise<TileResult> {
  const r = makeCpuRenderer(buildScene(a.spec), a.view, a.width, a.height, a, a.seed);
  const acc = newAccumulation(a.width, a.height);
  const passSpp = Math.max(1, Math.floor(a.passSpp));
  const passes = Math.max(1, Math.ceil(a.spp / passSpp));
  let paths = 0;
  let result: TileResult | null = null;
  for (let p = 0; p < passes; p++) {
    paths += renderTilePass(r, acc, a.tile, p, passSpp);
    result = {
      tile: a.tile,
      ...tileOf(a.tile, a.width, acc.sum, acc.count),
      passes: p + 1,
      spp: (p + 1) * passSpp,
      paths,
    };
    if (onPass) await onPass(result, (p + 1) / passes);
  }
  return result as TileResult;
}

/** Split a width × height image into `n` bands of whole rows (at most one per row). */
export function splitRows(width: number, height: number, n: number): Tile[] {
  const k = Math.max(1, Math.min(height, Math.floor(n)));
  const tiles: Tile[] = [];
  for (let b = 0; b < k; b++) {
    const y0 = Math.floor((b * height) / k);
    const y1 = Math.floor(((b + 1) * height) / k);
    tiles.push({ x0: 0, y0, w: width, h: y1 - y0 });
  }
  return tiles;
}

/** Copy a tile's sums and counts into a full-size accumulation (replacing what was there). */
export function mergeTile(
  acc: { width: number; sum: Float64Array; count: Uint32Array },
  r: TileResult,
): void {
  const { tile } = r;
  for (let y = 0; y < tile.h; y++) {
    const to = (tile.y0 + y) * acc.width + tile.x0;
    acc.sum.set(r.sum.subarray(y * tile.w, (y + 1) * tile.w), to);
    acc.count.set(r.count.subarray(y * tile.w, (y + 1) * tile.w), to);
  }
}
