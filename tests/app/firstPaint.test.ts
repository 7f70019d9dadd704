import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { runInNewContext } from 'node:vm';
import fc from 'fast-check';
import { parseHash, parseShellFlags } from '../../src/kit/shell';

// index.html sets the theme and the classroom/embed classes before the app's code has loaded (the
// page's first frames are in the link's colours); the app then sets the same. These tests hold the
// two in step.
const html = readFileSync(new URL('../../index.html', import.meta.url), 'utf8');

/** The first inline script of index.html's head. */
const headScript = /<head>[\s\S]*?<script>([\s\S]*?)<\/script>/.exec(html)![1];

/** What the head script leaves on <html> for a hash, with the system in `system` theme. */
function firstPaintState(hash: string, system: 'light' | 'dark') {
  const attrs: Record<string, string> = {};
  const classes = new Set<string>();
  const documentElement = {
    setAttribute: (k: string, v: string) => (attrs[k] = v),
    classList: { add: (c: string) => classes.add(c) },
  };
  const matchMedia = (q: string) => ({ matches: q === '(prefers-color-scheme: dark)' && system === 'dark' });
  const window = { matchMedia };
  runInNewContext(headScript, {
    location: { hash },
    document: { documentElement },
    window,
    matchMedia,
    URLSearchParams,
  });
  return { theme: attrs['data-theme'], present: classes.has('present'), embed: classes.has('embed') };
}

/** What the app sets for the same hash (App.tsx and theme.ts). */
function appState(hash: string, system: 'light' | 'dark') {
  const flags = parseShellFlags(parseHash(hash).query);
  return { theme: flags.theme ?? system, present: flags.present, embed: flags.embed };
}

describe("index.html's first paint", () => {
  it('sets the theme, present and embed as the app does, for the listed cases', () => {
    const cases: Array<[string, 'light' | 'dark']> = [
      ['', 'light'],
      ['#/', 'dark'],
      ['#/hemisphere?theme=dark', 'light'],
      ['#/hemisphere?theme=light', 'dark'],
      ['#/texture?theme=blue&present=1', 'dark'],
      ['#/ray-sphere?present=true&embed=1', 'light'],
      ['#/area-light?present=0&embed=false', 'light'],
      ['#/monte-carlo?present=yes', 'light'],
      ['#/?present=1?theme=dark', 'light'],
      ['#/%E0%A4%A?theme=dark', 'light'],
    ];
    for (const [hash, system] of cases)
      expect(firstPaintState(hash, system), hash).toEqual(appState(hash, system));
    // not vacuous: the cases reach each outcome
    const seen = cases.map(([h, s]) => firstPaintState(h, s));
    expect(new Set(seen.map((s) => s.theme))).toEqual(new Set(['light', 'dark']));
    expect(seen.some((s) => s.present) && seen.some((s) => s.embed)).toBe(true);
  });

  it('agrees with the app for any address made of the flags and stray text', () => {
    const value = fc.constantFrom('1', '0', 'true', 'false', 'dark', 'light', '', 'x', '%20');
    const pair = fc.tuple(fc.constantFrom('theme', 'present', 'embed', 'seed', 'th%65me'), value);
    const hash = fc
      .tuple(
        fc.constantFrom('#/', '#/hemisphere', '', '#', '#/practice/q1'),
        fc.array(pair, { maxLength: 5 }),
        fc.string(),
      )
      .map(([p, kv, junk]) => `${p}?${kv.map(([k, v]) => `${k}=${v}`).join('&')}${junk}`);
    fc.assert(
      fc.property(hash, fc.constantFrom('light' as const, 'dark' as const), (h, system) => {
        expect(firstPaintState(h, system)).toEqual(appState(h, system));
      }),
      { seed: 20261206, numRuns: 400 },
    );
  });
});
