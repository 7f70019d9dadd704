/**
 * The class results page's worker: parses and collates the results files (./collate.ts) off the
 * page's thread, reporting each file as it starts. Cancel terminates it (src/workers/run.ts).
 */
import { exposeTasks, type ProgressFn } from '../workers/expose';
import { raise, fail } from '../core/failure';
import { loadExpressionEngine } from '../core/expr';
import { collate, type InputFile } from './collate';

/** What the page hears while a collation runs: files done, and the file being checked. */
export interface CollateStep {
  done: number;
  current?: string;
}

const tasks = {
  collate: async (files: InputFile[], progress: ProgressFn<CollateStep>) => {
    // without the answer checker every answer would read as invalid: refuse instead
    await loadExpressionEngine().catch(() =>
      raise(fail('unavailable', 'the answer checker could not be loaded; reload the page while online once')),
    );
    return collate(files, (done, current) =>
      progress(files.length ? done / files.length : 1, current === undefined ? { done } : { done, current }),
    );
  },
};
exposeTasks(tasks);

/** The worker's tasks, for workerFactory<ResultsTasks> on the page's side. */
export type ResultsTasks = typeof tasks;
