/**
 * The t-tests a page shows on its first screen (ui/TTestLine: Student's t, Welch's map) need no
 * incomplete gamma function. That is the χ² test's (@stdlib, about 19 kB gzipped), run in workers
 * and folds; reached from a t-test line, it would be downloaded, and its module code run, before
 * the first paint of every scene that shows one.
 */
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { closure } from './importGraph';

const src = path.resolve(__dirname, '../../src');

describe('the t-tests stay light', () => {
  for (const file of ['ui/TTestLine.tsx', 'core/verify/ttest.ts', 'core/verify/welchMap.ts'])
    it(`${file} reaches no @stdlib package`, () => {
      const { files, packages } = closure(path.join(src, file));
      expect(files.length).toBeGreaterThan(1);
      expect(packages.filter((p) => p.startsWith('@stdlib/'))).toEqual([]);
    });
});
