/** The fuzzer runs only in a build made for it, and only when the route asks. */
import { describe, expect, it } from 'vitest';
import { fuzzBuild, fuzzRequest } from '../../src/app/fuzzGate';

const PRODUCTION = { DEV: false };
const DEV = { DEV: true };
const TEST_BUILD = { DEV: false, VITE_RML_FUZZ: '1' };

describe('fuzz gate', () => {
  it('a production build never runs it, whatever the link says', () => {
    expect(fuzzBuild(PRODUCTION)).toBe(false);
    for (const flags of [
      PRODUCTION,
      { DEV: false, VITE_RML_FUZZ: '0' },
      { DEV: false, VITE_RML_FUZZ: 'true' },
    ])
      for (const hash of [
        '#/practice?fuzz=1',
        '#/results?fuzz=1&seed=7',
        '#/?fuzz=1&fuzzn=300&fuzzseed=3',
        '#/texture?u=0.5&fuzz=1',
      ])
        expect(fuzzRequest(flags, hash)).toBeNull();
  });
  it('a development or test build runs it when the route asks, with its seed and limit', () => {
    expect(fuzzRequest(DEV, '#/practice?fuzz=1&seed=7')).toEqual({ seed: 7, limit: null });
    expect(fuzzRequest(TEST_BUILD, '#/?fuzz=1&fuzzseed=3&seed=9&fuzzn=300')).toEqual({ seed: 3, limit: 300 });
    expect(fuzzRequest(TEST_BUILD, '#/texture?fuzz=1&fuzzn=0&seed=x')).toEqual({ seed: 1, limit: null });
    for (const hash of ['#/practice', '#/practice?fuzz=0', '#/practice?fuzz=true', '#/practice?xfuzz=1', ''])
      expect(fuzzRequest(DEV, hash)).toBeNull();
  });
});
