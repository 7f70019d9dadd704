/** Worker of the hemisphere scene: runs ./jobs off the main thread (cancel = terminate, src/workers/run.ts). */
import { exposeTasks, type ProgressFn } from '../../workers/expose';
import { compileExpression } from '../../core/expr';
import { repeatJob, statsJob, type Compile2, type RepeatArgs, type StatsArgs } from './jobs';

const compile: Compile2 = async (src, vars) => {
  const r = await compileExpression(src, vars);
  return r.ok ? { ok: true, fn: r.fn as (...args: number[]) => number } : r;
};

const tasks = {
  stats: (a: StatsArgs) => statsJob(a, compile),
  repeat: (a: RepeatArgs, progress: ProgressFn) => repeatJob(a, compile, progress),
};
exposeTasks(tasks);

/** The worker's tasks, for workerFactory<HemisphereTasks> on the page's side. */
export type HemisphereTasks = typeof tasks;
