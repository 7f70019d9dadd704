import { describe, expect, it } from 'vitest';
import { parseHash, parseShellFlags } from '../../src/kit/shell';

describe('parseHash', () => {
  it('splits path and query and normalises the path', () => {
    expect(parseHash('')).toEqual({ path: '/', query: '' });
    expect(parseHash('#')).toEqual({ path: '/', query: '' });
    expect(parseHash('#/texture?u=0.4&v=0.24')).toEqual({ path: '/texture', query: 'u=0.4&v=0.24' });
    expect(parseHash('#texture/')).toEqual({ path: '/texture', query: '' });
    expect(parseHash('#/?present=1')).toEqual({ path: '/', query: 'present=1' });
  });
});

describe('parseShellFlags', () => {
  it('reads embed, present and theme, and reports garbage', () => {
    expect(parseShellFlags('embed=1&present=true&theme=dark')).toMatchObject({
      embed: true,
      present: true,
      theme: 'dark',
      problems: [],
    });
    const f = parseShellFlags('embed=yes&theme=purple');
    expect(f.embed).toBe(false);
    expect(f.theme).toBeNull();
    expect(f.problems.map((p) => p.name)).toEqual(['embed', 'theme']);
  });
});
