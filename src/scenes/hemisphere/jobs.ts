/**
 * The long computations of the hemisphere scene as plain async functions of plain data: drawing n
 * samples (up to 10⁶) with the χ² test, histograms and Q2 estimators; the "repeat many times"
 * runs; and the points the 3D view draws (directions, colours, (ξ₁, ξ₂)), streamed in chunks. They run in hemisphere.worker.ts and in unit tests alike; the user expressions are compiled
 * here again (closures cannot cross the worker boundary), by the `compile` the caller passes.
 */
import { fail, raise, type Failure } from '../../core/failure';
import { fillSequence2D, type SequenceKind } from '../../core/random';
import { computeDrawStats, type DrawStats } from './drawStats';
import { lobeFromParams, type Lobe } from './lobe';
import { repeatEstimates } from './q2Estimates';
import type { Integrand } from './integral';
import type { HemisphereParams, LobeId } from './params';
import { xiColor } from './view/colors';

/** Compiles a user expression in (theta, phi) (the worker passes core/expr's compiler). */
export type Compile2 = (
  src: string,
  vars: string[],
) => Promise<{ ok: true; fn: (...args: number[]) => number } | Failure>;

export interface StatsArgs {
  lobe: LobeId;
  exponent: number;
  pdf: string;
  f: string;
  points: SequenceKind;
  seed: number;
  n: number;
  /** false when the key's inverted Jacobian is selected: no lobe can be sampled. */
  sampleLobe: boolean;
}

export interface RepeatArgs extends StatsArgs {
  runs: number;
  perRun: number;
}

export interface RepeatResult {
  uniform: Float64Array;
  importance: Float64Array;
}

type Progress = (fraction: number, partial?: unknown) => void;

/** What the 3D view's points depend on: the lobe (its exponent, its typed density) and the point set. */
export interface PointsArgs {
  lobe: LobeId;
  exponent: number;
  pdf: string;
  points: SequenceKind;
  seed: number;
  n: number;
}

/** Points [start, start + count) of the view: directions and (ξ₁, ξ₂) in float32, colours in bytes. */
export interface PointsChunk {
  start: number;
  count: number;
  pos: Float32Array;
  col: Uint8Array;
  xi: Float32Array;
}

/**
 * The view's point arguments for the scene's parameters, with what the lobe does not read left at
 * a fixed value (the exponent outside Phong, the typed density outside 'custom'), so that editing
 * them does not restart the points.
 */
export function pointsArgsOf(
  p: Pick<HemisphereParams, 'lobe' | 'exponent' | 'pdf' | 'points' | 'seed' | 'n'>,
): PointsArgs {
  return {
    lobe: p.lobe,
    exponent: p.lobe === 'phong' ? p.exponent : 0,
    pdf: p.lobe === 'custom' ? p.pdf : '',
    points: p.points,
    seed: p.seed,
    n: p.n,
  };
}

/** The lobe the parameters name (compiling the typed density for 'custom'); null when there is none. */
async function lobeOf(
  a: Pick<PointsArgs, 'lobe' | 'exponent' | 'pdf'>,
  compile: Compile2,
): Promise<Lobe | null> {
  let density: Integrand | null = null;
  if (a.lobe === 'custom') {
    const pc = await compile(a.pdf, ['theta', 'phi']);
    if (pc.ok) density = (t, p) => pc.fn(t, p);
  }
  return lobeFromParams(a.lobe, a.exponent, density).lobe;
}

/** Compile f (and the typed density when the lobe is 'custom'), build the lobe the page shows. */
export async function prepare(
  a: StatsArgs,
  compile: Compile2,
): Promise<{ lobe: Lobe | null; f: Integrand | null; fFailure: Failure | null }> {
  const fc = await compile(a.f, ['theta', 'phi']);
  const f = fc.ok ? (t: number, p: number) => fc.fn(t, p) : null;
  const lobe = a.sampleLobe ? await lobeOf(a, compile) : null;
  return { lobe, f, fFailure: fc.ok ? null : fc };
}

export async function statsJob(a: StatsArgs, compile: Compile2): Promise<DrawStats> {
  const { lobe, f } = await prepare(a, compile);
  return computeDrawStats(lobe, f, a.points, a.seed, a.n);
}

export async function repeatJob(
  a: RepeatArgs,
  compile: Compile2,
  progress: Progress = () => {},
): Promise<RepeatResult> {
  const { lobe, f, fFailure } = await prepare(a, compile);
  if (!f) raise(fail(fFailure?.kind ?? 'compile', 'the integrand does not compile'));
  return repeatEstimates(lobe, f, a.points, a.seed, a.runs, a.perRun, (x) => progress(x));
}

/** Scratch of {@link fillPoints}: (ξ₁, ξ₂) and directions in float64 for one batch. */
export interface PointsScratch {
  u: Float64Array;
  d: Float64Array;
}

const POINTS_BATCH = 1 << 14;

export function pointsScratch(): PointsScratch {
  return { u: new Float64Array(2 * POINTS_BATCH), d: new Float64Array(3 * POINTS_BATCH) };
}

/**
 * Points [start, end) of the lobe's n samples into the chunk's arrays (point i at index i − start):
 * the direction lobe.sampleBatch gives it (as the statistics use), its (ξ₁, ξ₂) and its colour.
 */
export function fillPoints(
  lobe: Lobe,
  kind: SequenceKind,
  seed: number,
  n: number,
  start: number,
  end: number,
  out: Pick<PointsChunk, 'pos' | 'col' | 'xi'>,
  scratch: PointsScratch = pointsScratch(),
): void {
  const { u, d } = scratch;
  const { pos, col, xi } = out;
  for (let s = start; s < end; s += POINTS_BATCH) {
    const e = Math.min(end, s + POINTS_BATCH);
    const m = e - s;
    fillSequence2D(kind, seed, n, u, s, e, 0);
    lobe.sampleBatch(u, d, m);
    const o = s - start;
    for (let i = 0; i < m; i++) {
      const j = 3 * (o + i);
      pos[j] = d[3 * i];
      pos[j + 1] = d[3 * i + 1];
      pos[j + 2] = d[3 * i + 2];
      xi[2 * (o + i)] = u[2 * i];
      xi[2 * (o + i) + 1] = u[2 * i + 1];
      xiColor(u[2 * i], u[2 * i + 1], col, j);
    }
  }
}

/** A chunk of `count` points from `start`, with its own arrays (transferable). */
export function pointsChunk(start: number, count: number): PointsChunk {
  return {
    start,
    count,
    pos: new Float32Array(3 * count),
    col: new Uint8Array(3 * count),
    xi: new Float32Array(2 * count),
  };
}

/** Chunk sizes of the stream: a small first one (on screen soon), then doubling up to 2¹⁶ points. */
export const FIRST_CHUNK = 2048;
export const MAX_CHUNK = 1 << 16;

/**
 * The 3D view's n points, streamed: each chunk goes out through `progress` as soon as it is filled
 * (its arrays transferred), in order, so the page only copies them into its buffers. Refuses when
 * the parameters name no density to sample.
 */
export async function pointsJob(
  a: PointsArgs,
  compile: Compile2,
  progress: (fraction: number, chunk: PointsChunk) => void,
): Promise<{ n: number }> {
  const lobe = await lobeOf(a, compile);
  if (!lobe) raise(fail('no-density', 'no valid density to sample'));
  const scratch = pointsScratch();
  for (let s = 0, size = FIRST_CHUNK; s < a.n; s += size, size = Math.min(MAX_CHUNK, 2 * size)) {
    const c = pointsChunk(s, Math.min(size, a.n - s));
    fillPoints(lobe, a.points, a.seed, a.n, s, s + c.count, c, scratch);
    progress((s + c.count) / a.n, c);
  }
  return { n: a.n };
}
