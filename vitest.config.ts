import { availableParallelism } from 'node:os';
import { defineConfig } from 'vitest/config';

/**
 * Coverage floors per layer (`npm run coverage`, part of `npm test`), in % of statements, branches,
 * functions and lines: each three points under what the unit suite measured (the comment above
 * it), so that a change which leaves a layer's code untested fails the run. The views and scenes
 * are low because the browser tests (tests/e2e), which the unit run does not count, cover them.
 */
const FLOORS: Record<string, { statements: number; branches: number; functions: number; lines: number }> = {
  // measured 96.6 / 89.3 / 96.2 / 98.1 %
  'src/core/**': { statements: 93, branches: 86, functions: 93, lines: 95 },
  // measured 84.5 / 77.9 / 79.2 / 87.1 %
  'src/kit/**': { statements: 81, branches: 74, functions: 76, lines: 84 },
  // measured 38.9 / 35.7 / 28.1 / 39.7 %
  'src/ui/**': { statements: 35, branches: 32, functions: 25, lines: 36 },
  // measured 36.8 / 28.0 / 28.9 / 36.9 %
  'src/scenes/**': { statements: 33, branches: 25, functions: 25, lines: 33 },
  // measured 70.5 / 63.0 / 63.7 / 72.5 %
  'src/practice/**': { statements: 67, branches: 60, functions: 60, lines: 69 },
  // measured 43.9 / 26.4 / 57.8 / 45.2 %
  'src/lms/**': { statements: 40, branches: 23, functions: 54, lines: 42 },
  // measured 38.0 / 39.9 / 17.9 / 38.9 %
  'src/results/**': { statements: 35, branches: 36, functions: 14, lines: 35 },
  // measured 65.7 / 71.4 / 43.3 / 66.8 %
  'src/deck/**': { statements: 62, branches: 68, functions: 40, lines: 63 },
};

export default defineConfig({
  test: {
    include: ['tests/**/*.test.ts', 'tests/**/*.test.tsx'],
    exclude: ['tests/e2e/**', 'node_modules/**'],
    environment: 'node',
    // generous: the suite must pass on a busy 2-core machine (tests assert results, never timings)
    testTimeout: 120_000,
    pool: 'threads',
    // every core: the default leaves one free (one worker on a 2-core machine, where two take the
    // suite from about 58 s to 38 s)
    maxWorkers: availableParallelism(),
    // one module cache per worker thread, not per file: the suite imports mathjs, three and the
    // scenes' models once per thread instead of once per file (about half of its run time); no
    // test relies on a fresh module state
    isolate: false,
    coverage: {
      provider: 'v8',
      include: ['src/**/*.{ts,tsx}'],
      exclude: ['src/**/*.d.ts', 'src/**/*.worker.ts'],
      reporter: ['text-summary', 'json-summary'],
      reportsDirectory: 'coverage',
      thresholds: FLOORS,
    },
  },
});
