/** Worker of the hemisphere scene: runs ./jobs off the main thread (cancel = terminate, src/workers/run.ts). */
import { exposeTasks, type ProgressFn } from '../../workers/expose';
import {
  pointsJob,
  repeatJob,
  statsJob,
  type Compile2,
  type PointsArgs,
  type PointsChunk,
  type RepeatArgs,
  type StatsArgs,
} from './jobs';
import { checkGpuDirections, type GpuCheckArgs } from './gpuCheck';

// the expression compiler (mathjs) loads on first use: the 3D view's points of a built-in lobe
// need none, and they are what the scene's first screen waits for
const compile: Compile2 = async (src, vars) => {
  const { compileExpression } = await import('../../core/expr');
  const r = await compileExpression(src, vars);
  return r.ok ? { ok: true, fn: r.fn as (...args: number[]) => number } : r;
};

const tasks = {
  stats: (a: StatsArgs) => statsJob(a, compile),
  repeat: (a: RepeatArgs, progress: ProgressFn) => repeatJob(a, compile, progress),
  points: (a: PointsArgs, progress: ProgressFn<PointsChunk>) => pointsJob(a, compile, progress),
  gpuCheck: (a: GpuCheckArgs) => checkGpuDirections(a),
};
exposeTasks(tasks);

/** The worker's tasks, for workerFactory<HemisphereTasks> on the page's side. */
export type HemisphereTasks = typeof tasks;
