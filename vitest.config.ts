import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    include: ['tests/**/*.test.ts', 'tests/**/*.test.tsx'],
    exclude: ['tests/e2e/**', 'node_modules/**'],
    environment: 'node',
    // generous: the suite must pass on a busy 2-core machine (tests assert results, never timings)
    testTimeout: 120_000,
    pool: 'threads',
  },
});
