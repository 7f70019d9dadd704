import { describe, expect, it } from 'vitest';
import { parseShellFlags, queryProblems, shellExtras } from '../../src/kit/shell';
import { parseParams, SHELL_PARAMS } from '../../src/kit/params';

describe('the a11y=1 shell flag (the A11y view)', () => {
  it('is read, reported when garbled, and kept in links the scene writes', () => {
    expect(parseShellFlags('a11y=1').a11y).toBe(true);
    expect(parseShellFlags('a11y=0').a11y).toBe(false);
    expect(parseShellFlags('').a11y ?? false).toBe(false);
    const bad = parseShellFlags('a11y=maybe');
    expect(bad.a11y ?? false).toBe(false);
    expect(bad.problems.map((p) => p.name)).toEqual(['a11y']);
    const f = parseShellFlags('a11y=1&theme=dark');
    expect(shellExtras(f).a11y).toBe('1');
    expect(shellExtras(parseShellFlags('theme=dark')).a11y).toBeUndefined();
  });

  it('is a shell parameter: no page and no scene calls it unknown', () => {
    expect(SHELL_PARAMS).toContain('a11y');
    expect(queryProblems('a11y=1', ['seed'])).toEqual([]);
    const parsed = parseParams({ u: { kind: 'number', default: 0.5, min: 0, max: 1 } }, 'u=0.4&a11y=1');
    expect(parsed.problems).toEqual([]);
  });
});
