/**
 * The class results page's worker: parses and collates the results files (./collate.ts) off the
 * page's thread, reporting each file as it starts; `warm` loads the answer checker ahead of the
 * first batch. The page keeps it between batches, and Cancel terminates it (./jobs.ts).
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

/** Load the answer checker: without it every answer would read as invalid, so refuse instead. */
const loadChecker = () =>
  loadExpressionEngine().then(
    () => true,
    () =>
      raise(fail('unavailable', 'the answer checker could not be loaded; reload the page while online once')),
  );

const tasks = {
  warm: () => loadChecker(),
  collate: async (files: InputFile[], progress: ProgressFn<CollateStep>) => {
    await loadChecker();
    return collate(files, (done, current) =>
      progress(files.length ? done / files.length : 1, current === undefined ? { done } : { done, current }),
    );
  },
};
exposeTasks(tasks);

/** The worker's tasks, for workerFactory<ResultsTasks> on the page's side. */
export type ResultsTasks = typeof tasks;
