/**
 * The teacher's guide's presets are real links: each one parses against its scene's schema with no
 * problem (no unknown, malformed or clamped parameter), every exam question has 3–5 presets, and
 * the links encode expression characters so that `+` stays a plus.
 */
import { describe, expect, it } from 'vitest';
import { LESSONS, MISCONCEPTIONS, presetHref } from '../../src/guide/lessons';
import { parseParams, type ParamSchema } from '../../src/kit/params';
import { parseHash } from '../../src/kit/shell';
import { SCENES } from '../../src/kit/catalogue';

// every scene's URL schema, by route, found the way the registry finds the scenes
const SCHEMAS = new Map<string, ParamSchema>(
  Object.entries(
    import.meta.glob<{ schema: ParamSchema }>('../../src/scenes/*/params.ts', { eager: true }),
  ).map(([file, mod]) => [`/${file.split('/').at(-2)}`, mod.schema]),
);
const monteCarlo = SCHEMAS.get('/monte-carlo')!;

describe('teacher’s guide', () => {
  it('has a lesson of 3–5 presets for each of the six exam questions', () => {
    expect(LESSONS.map((l) => l.question)).toEqual(['Q1', 'Q2', 'Q3', 'Q4', 'Q5', 'Q6']);
    for (const l of LESSONS) {
      expect(l.presets.length).toBeGreaterThanOrEqual(3);
      expect(l.presets.length).toBeLessThanOrEqual(5);
      for (const p of l.presets) expect(p.ask.trim().endsWith('?') || p.ask.includes('?')).toBe(true);
    }
  });

  it('every preset link opens a scene with every parameter used as given', () => {
    for (const l of LESSONS)
      for (const p of l.presets) {
        const href = presetHref(p);
        const route = parseHash(href);
        const schema = SCHEMAS.get(route.path);
        expect(schema, `${href}: a scene route`).toBeDefined();
        expect(SCENES.some((s) => s.path === route.path)).toBe(true);
        const parsed = parseParams(schema!, route.query);
        expect(parsed.problems, href).toEqual([]);
        // the values the scene gets are the ones the guide wrote
        for (const [k, v] of Object.entries(p.params)) {
          const got = (parsed.values as Record<string, unknown>)[k];
          const text = Array.isArray(got)
            ? got.join(',')
            : typeof got === 'boolean'
              ? got
                ? '1'
                : '0'
              : String(got);
          expect(text === v || Number(text) === Number(v), `${href}: ${k}`).toBe(true);
        }
      }
  });

  it('encodes expressions so that a plus stays a plus, and classroom links keep present=1', () => {
    const p = { route: '/monte-carlo', params: { f: 'x+1' }, title: '', shows: '', ask: '' };
    expect(presetHref(p)).toBe('#/monte-carlo?f=x%2B1');
    expect(parseParams(monteCarlo, parseHash(presetHref(p)).query).values.f).toBe('x+1');
    expect(presetHref(p, true)).toBe('#/monte-carlo?f=x%2B1&present=1');
  });

  it('lists misconceptions for every scene', () => {
    expect(MISCONCEPTIONS.map((m) => m.route).sort()).toEqual(SCENES.map((s) => s.path).sort());
    for (const m of MISCONCEPTIONS) expect(m.items.length).toBeGreaterThanOrEqual(3);
  });
});
