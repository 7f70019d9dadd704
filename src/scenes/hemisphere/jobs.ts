/**
 * The long computations of the hemisphere scene as plain async functions of plain data: drawing n
 * samples (up to 10⁶) with the χ² test, histograms and Q2 estimators; and the "repeat many times"
 * runs. They run in hemisphere.worker.ts and in unit tests alike; the user expressions are compiled
 * here again (closures cannot cross the worker boundary), by the `compile` the caller passes.
 */
import { fail, raise, type Failure } from '../../core/failure';
import type { SequenceKind } from '../../core/random';
import {
  computeDrawStats,
  lobeFromParams,
  repeatEstimates,
  type DrawStats,
  type Integrand,
  type Lobe,
} from './model';
import type { LobeId } from './params';

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

/** Compile f (and the typed density when the lobe is 'custom'), build the lobe the page shows. */
export async function prepare(
  a: StatsArgs,
  compile: Compile2,
): Promise<{ lobe: Lobe | null; f: Integrand | null; fFailure: Failure | null }> {
  const fc = await compile(a.f, ['theta', 'phi']);
  const f = fc.ok ? (t: number, p: number) => fc.fn(t, p) : null;
  let lobe: Lobe | null = null;
  if (a.sampleLobe) {
    let density: Integrand | null = null;
    if (a.lobe === 'custom') {
      const pc = await compile(a.pdf, ['theta', 'phi']);
      if (pc.ok) density = (t, p) => pc.fn(t, p);
    }
    lobe = lobeFromParams(a.lobe, a.exponent, density).lobe;
  }
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
