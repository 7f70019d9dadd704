import { describe, expect, it } from 'vitest';
import {
  addressKey,
  dropQueryParam,
  parseHash,
  parseShellFlags,
  queryProblems,
  shellExtras,
} from '../../src/kit/shell';

describe('parseHash', () => {
  it('splits path and query and normalises the path', () => {
    expect(parseHash('')).toEqual({ path: '/', query: '' });
    expect(parseHash('#')).toEqual({ path: '/', query: '' });
    expect(parseHash('#/texture?u=0.4&v=0.24')).toEqual({ path: '/texture', query: 'u=0.4&v=0.24' });
    expect(parseHash('#texture/')).toEqual({ path: '/texture', query: '' });
    expect(parseHash('#/?present=1')).toEqual({ path: '/', query: 'present=1' });
  });
});

describe('addressKey', () => {
  it('leaves out the page’s own rewrites (open=, ask=) and keeps everything a followed link changes', () => {
    const key = addressKey('#/hemisphere?lobe=custom&pdf=cos(theta)&open=settings');
    expect(addressKey('#/hemisphere?lobe=custom&pdf=cos(theta)')).toBe(key);
    expect(addressKey('#/hemisphere?lobe=custom&ask=1&pdf=cos(theta)&open=x,y')).toBe(key);
    expect(addressKey('#/hemisphere?lobe=phong&exponent=8&n=1500&seed=7')).not.toBe(key);
    expect(addressKey('#/hemisphere?lobe=custom&pdf=cos(theta)&present=1')).not.toBe(key);
    expect(addressKey('#/monte-carlo?lobe=custom&pdf=cos(theta)')).not.toBe(key);
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

describe('ask=1 (ask, then reveal)', () => {
  it('is off unless asked, on for 1 or true, off for 0 or false', () => {
    expect(parseShellFlags('').ask).toBe(false);
    for (const v of ['1', 'true']) expect(parseShellFlags(`ask=${v}`).ask).toBe(true);
    for (const v of ['0', 'false']) {
      const f = parseShellFlags(`ask=${v}`);
      expect(f.ask).toBe(false);
      expect(f.problems).toEqual([]);
    }
  });

  it('reports a bad value and falls back to not asking', () => {
    const f = parseShellFlags('ask=maybe&present=1');
    expect(f.ask).toBe(false);
    expect(f.present).toBe(true);
    expect(f.problems).toEqual([{ name: 'ask', message: '"maybe" is not 0 or 1; ignored' }]);
  });

  it('uses the first of repeated values, and says so', () => {
    const f = parseShellFlags('ask=1&ask=0');
    expect(f.ask).toBe(true);
    expect(f.problems).toEqual([{ name: 'ask', message: 'is given 2 times; using the first' }]);
  });

  it('is a shell parameter: not reported as unknown on pages without a schema', () => {
    expect(queryProblems('ask=1&present=1', [])).toEqual([]);
    expect(queryProblems('ask=1&nope=2', [])).toEqual([
      { name: 'nope', message: 'is not a parameter of this page; ignored' },
    ]);
  });

  it('goes into links that keep the mode only when on', () => {
    const base = { embed: false, present: true, theme: null };
    expect(shellExtras({ ...base, ask: true }).ask).toBe('1');
    expect(shellExtras({ ...base, ask: false }).ask).toBeUndefined();
    expect(shellExtras(base).ask).toBeUndefined();
  });
});

describe('dropQueryParam', () => {
  it('removes every entry of one name and keeps the rest exactly as written', () => {
    expect(dropQueryParam('lobe=exam&ask=1&o=-3,0.3,0.2&f=x%2B1', 'ask')).toBe(
      'lobe=exam&o=-3,0.3,0.2&f=x%2B1',
    );
    expect(dropQueryParam('ask=1', 'ask')).toBe('');
    expect(dropQueryParam('?ask=1&ask=0&present=1', 'ask')).toBe('present=1');
    expect(dropQueryParam('', 'ask')).toBe('');
    // an encoded name is the same name; a malformed escape is left alone
    expect(dropQueryParam('%61sk=1&a=%E0%A4%A', 'ask')).toBe('a=%E0%A4%A');
    expect(dropQueryParam('%zz=1&asking=1', 'ask')).toBe('%zz=1&asking=1');
  });
});
