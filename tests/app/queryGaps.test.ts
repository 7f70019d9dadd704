/**
 * Small gaps of a link: repeated shell parameters and unknown names on pages without a scene
 * schema are named; a non-zero number that underflows to 0 is named, not taken silently.
 */
import { describe, expect, it } from 'vitest';
import { parseShellFlags, queryProblems } from '../../src/kit/shell';
import { parseParams } from '../../src/kit/params';
import { schema as texture } from '../../src/scenes/texture/params';

describe('link gaps', () => {
  it('names a repeated shell parameter', () => {
    const f = parseShellFlags('theme=dark&theme=bogus');
    expect(f.theme).toBe('dark');
    expect(f.problems).toEqual([{ name: 'theme', message: 'is given 2 times; using the first' }]);
  });
  it('names unknown and repeated parameters of a page without a schema', () => {
    expect(queryProblems('seed=7&seed=8&bogus=1&theme=dark', ['seed'])).toEqual([
      { name: 'seed', message: 'is given 2 times; using the first' },
      { name: 'bogus', message: 'is not a parameter of this page; ignored' },
    ]);
    expect(queryProblems('present=1&fuzz=1', [])).toEqual([]);
    expect(queryProblems('constructor=1', []).map((p) => p.name)).toEqual(['constructor']);
  });
  it('names a number that underflows to 0, and keeps real zeros silent', () => {
    const r = parseParams(texture, 'u=1e-400');
    expect(r.values.u).toBe(0);
    expect(r.problems.map((p) => p.name)).toEqual(['u']);
    expect(r.problems[0].message).toMatch(/rounds to 0/);
    for (const zero of ['0', '0.000', '-0', '0e5', '0e-400'])
      expect(parseParams(texture, `u=${zero}`).problems, zero).toEqual([]);
  });
});
