/**
 * The teacher's guide's presets are real links: each one parses against its scene's schema with no
 * problem (no unknown, malformed or clamped parameter), every exam question has 3–5 presets, and
 * the links encode expression characters so that `+` stays a plus.
 */
import { describe, expect, it } from 'vitest';
import { LESSONS, MISCONCEPTIONS, presetHref } from '../../src/guide/lessons';
import { parseParams, type ParamSchema } from '../../src/app/params';
import { parseHash } from '../../src/app/route';
import { SCENES } from '../../src/scenes/registry';
import { schema as hemisphere } from '../../src/scenes/hemisphere/params';
import { schema as monteCarlo } from '../../src/scenes/monte-carlo/params';
import { schema as texture } from '../../src/scenes/texture/params';
import { schema as raySphere } from '../../src/scenes/ray-sphere/params';
import { schema as areaLight } from '../../src/scenes/area-light/params';

const SCHEMAS = new Map<string, ParamSchema>([
  ['/hemisphere', hemisphere],
  ['/monte-carlo', monteCarlo],
  ['/texture', texture],
  ['/ray-sphere', raySphere],
  ['/area-light', areaLight],
]);

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
