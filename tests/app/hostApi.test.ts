/**
 * The host API's validation: a `set` is read exactly like URL parameters (parseParams), all or
 * nothing, with every problem named; own keys only; shell parameters refused; origin= parsing.
 */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { validateSet, toUrlText, typeProblem, versionError } from '../../src/app/hostApi';
import { parseOrigins, parseShellFlags, shellExtras } from '../../src/kit/shell';
import { parseParams, serializeParams } from '../../src/kit/params';
import { schema as texture } from '../../src/scenes/texture/params';
import { schema as raySphere } from '../../src/scenes/ray-sphere/params';

describe('validateSet', () => {
  it('accepts what the URL accepts, with the same values', () => {
    const r = validateSet(texture, { u: 0.7, v: '0.3', wrap: 'repeat', vflip: true });
    expect(r).toEqual({ ok: true, patch: { u: 0.7, v: 0.3, wrap: 'repeat', vflip: true } });
    const v = validateSet(raySphere, { o: [1, 2, 3], method: 'textbook' });
    expect(v).toEqual({ ok: true, patch: { o: [1, 2, 3], method: 'naive' } });
  });

  it('names every value it cannot use, and applies none of them', () => {
    const r = validateSet(texture, { u: 'abc', wrap: 'sideways', v: 0.5 });
    expect(r.ok).toBe(false);
    if (r.ok) return;
    expect(r.problems.map((p) => p.name).sort()).toEqual(['u', 'wrap']);
    expect(r.problems.find((p) => p.name === 'wrap')!.message).toContain('sideways');
    // the URL parser's "using the default" tail is dropped: nothing is applied
    for (const p of r.problems) expect(p.message).not.toMatch(/using/);
  });

  it('treats out-of-range values as errors (the URL would clamp them with a notice)', () => {
    const r = validateSet(texture, { u: 10 });
    expect(r.ok).toBe(false);
  });

  it('refuses unknown names, prototype names, shell parameters and non-plain values', () => {
    for (const name of [
      'bogus',
      'toString',
      '__proto__',
      'constructor',
      'hasOwnProperty',
      'embed',
      'present',
      'theme',
      'origin',
    ]) {
      const params = JSON.parse(`{${JSON.stringify(name)}: 1}`) as Record<string, unknown>;
      const r = validateSet(texture, params);
      expect(r.ok, name).toBe(false);
    }
    for (const bad of [{ u: null }, { u: { valueOf: 1 } }, { o: ['1', 2, 3] }, { u: NaN }, { u: Infinity }])
      expect(validateSet(raySphere, bad).ok).toBe(false);
    for (const bad of [null, 'u=1', [1, 2], 42]) expect(validateSet(texture, bad).ok).toBe(false);
  });

  it('agrees with the URL parser on arbitrary values (property)', () => {
    fc.assert(
      fc.property(
        fc.oneof(fc.double(), fc.string({ maxLength: 12 }), fc.boolean()),
        fc.constantFrom('u', 'v', 'wrap', 'vflip', 'size'),
        (value, name) => {
          const text = toUrlText(value)!;
          const url = parseParams(texture, new URLSearchParams([[name, text]]));
          const r = validateSet(texture, { [name]: value });
          // accepted exactly when the URL would take the text and the value has the parameter's type
          expect(r.ok).toBe(url.problems.length === 0 && typeProblem(texture[name], value) === null);
          if (r.ok) expect(r.patch[name]).toEqual((url.values as Record<string, unknown>)[name]);
        },
      ),
      { numRuns: 300, seed: 14 },
    );
  });

  it('converts no type silently', () => {
    for (const bad of [
      { u: true },
      { u: [0.7] },
      { u: false },
      { vflip: 'yes' },
      { vflip: 2 },
      { wrap: 'repeat ' },
      { wrap: ' repeat' },
      { wrap: 1 },
      { grid: [1, 2, 3] },
      { grid: [] },
      { grid: 5 },
      { u: ' 0.7' },
    ]) {
      const r = validateSet(texture, bad);
      expect(r.ok, JSON.stringify(bad)).toBe(false);
      if (!r.ok) expect(r.problems.map((p) => p.name)).toEqual(Object.keys(bad));
    }
    expect(validateSet(raySphere, { r: [2] }).ok).toBe(false);
    expect(validateSet(raySphere, { o: 1 }).ok).toBe(false);
    // what the README documents still works: typed values, and URL text
    for (const good of [
      { u: 0.7 },
      { u: '0.7' },
      { vflip: true },
      { vflip: 1 },
      { vflip: '0' },
      { wrap: 'repeat' },
      { grid: '1,2;3,4' },
      { grid: ' 1,2;3,4' },
    ])
      expect(validateSet(texture, good).ok, JSON.stringify(good)).toBe(true);
    expect(validateSet(raySphere, { o: [0, 0, -5], r: 2 }).ok).toBe(true);
    expect(validateSet(raySphere, { o: '0,0,-5' }).ok).toBe(true);
  });

  it('says what is wrong with a version', () => {
    expect(versionError('1')).toMatch(/"1" is a string; send version: 1 \(the number 1\)/);
    expect(versionError(2)).toMatch(/version 2 is not supported; this app speaks version 1/);
    expect(versionError(undefined)).toMatch(/no version/);
    expect(versionError({})).toMatch(/an object/);
  });

  it('round-trips: what get reports, set accepts unchanged', () => {
    const values = parseParams(texture, 'u=0.7&wrap=mirror&preset=checker').values;
    const r = validateSet(texture, values as Record<string, unknown>);
    expect(r.ok).toBe(true);
    if (r.ok)
      expect(serializeParams(texture, { ...values, ...r.patch })).toBe(serializeParams(texture, values));
  });
});

describe('origin=', () => {
  it('reads a comma list of exact origins and names the rest', () => {
    expect(parseOrigins('https://lms.example.edu,http://127.0.0.1:8080')).toEqual({
      origins: ['https://lms.example.edu', 'http://127.0.0.1:8080'],
      problem: null,
    });
    const r = parseOrigins('https://lms.example.edu/course/1,javascript:alert(1),*');
    expect(r.origins).toEqual([]);
    expect(r.problem).toContain('javascript');
    expect(parseShellFlags('origin=https%3A%2F%2Flms.example.edu').origins).toEqual([
      'https://lms.example.edu',
    ]);
    expect(parseShellFlags('origin=nope').problems.map((p) => p.name)).toEqual(['origin']);
    // origin is a shell parameter: a scene does not call it unknown
    expect(parseParams(texture, 'origin=https%3A%2F%2Fx.org').problems).toEqual([]);
  });

  it('never widens who is answered: a present origin= with no usable entry answers nobody, and says so', () => {
    expect(parseOrigins(null)).toEqual({ origins: null, problem: null });
    expect(parseShellFlags('u=0.3').origins).toBeNull();
    for (const raw of [
      'http://127.0.0.1:4304/lms/page',
      '127.0.0.1:4304',
      'HTTP://127.0.0.1:4304',
      'null',
      '*',
      '',
      ' , ,',
      'file:///x',
      'javascript:alert(1)',
    ]) {
      const r = parseOrigins(raw);
      expect(r.origins, raw).toEqual([]);
      expect(r.problem, raw).toMatch(/no usable origin/);
      const f = parseShellFlags(`origin=${encodeURIComponent(raw)}`);
      expect(f.origins, raw).toEqual([]);
      expect(
        f.problems.map((p) => p.name),
        raw,
      ).toEqual(['origin']);
      // a link the page rewrites keeps the (closed) restriction
      expect(shellExtras(f).origin, raw).toBe('');
    }
    expect(parseShellFlags('origin=').origins).toEqual([]);
  });

  it('keeps the first 16 origins and names the dropped ones', () => {
    const list = Array.from({ length: 17 }, (_, i) => `https://h${i}.example.edu`);
    const r = parseOrigins(list.join(','));
    expect(r.origins).toEqual(list.slice(0, 16));
    expect(r.problem).toMatch(/17 origins; only the first 16/);
    expect(r.problem).toContain('h16.example.edu');
    expect(parseOrigins(list.slice(0, 16).join(',')).problem).toBeNull();
    // a repeated origin counts once
    expect(parseOrigins('https://a.org,https://a.org').origins).toEqual(['https://a.org']);
  });
});
