/**
 * The teacher's guide's presets are real links: each one parses against its scene's schema with no
 * problem (no unknown, malformed or clamped parameter), every exam question has 3–5 presets, and
 * the links encode expression characters so that `+` stays a plus.
 */
import { describe, expect, it } from 'vitest';
import { LESSONS, MISCONCEPTIONS, presetHref } from '../../src/guide/lessons';
import { parseParams, type ParamSchema } from '../../src/kit/params';
import { parseHash } from '../../src/kit/shell';
import { SCENES, predictPrompt } from '../../src/kit/catalogue';
import { presetAskFor } from '../../src/kit/lessons';

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

  it('each preset lands where its text says: its part, ask=1 when it asks first, t=0 before an animation', () => {
    for (const l of LESSONS)
      for (const p of l.presets) {
        const href = presetHref(p);
        const scene = SCENES.find((s) => s.path === p.route)!;
        const sp = new URLSearchParams(parseHash(href).query);
        if (p.part) {
          expect(scene.parts, `${href}: part ${p.part} is on its scene`).toContain(p.part);
          expect(sp.get('part'), href).toBe(p.part);
        } else expect(sp.has('part'), href).toBe(false);
        expect(sp.get('ask'), href).toBe(p.askFirst ? '1' : null);
        // a title naming an exam part of this scene ("(Q6a, Q6b)") lands on the first one named
        const named = /\(Q(\d[a-d]?)/.exec(p.title)?.[1];
        if (named && scene.parts.includes(named)) expect(p.part, `${href}: ${p.title}`).toBe(named);
        // a question about what happens next opens before it happens, in ask mode
        if (/^before (you play|the race runs|the samples are drawn|you reveal the points)/i.test(p.ask)) {
          expect(p.params.t, `${href}: opens at the start of its animation`).toBe('0');
          expect(p.askFirst, href).toBe(true);
        }
        if (p.params.t !== undefined) expect(p.askFirst, `${href}: held at t=0 for a prediction`).toBe(true);
      }
  });

  it('an ask=1 page opened from a preset link finds that preset’s question, whatever the shell flags', () => {
    for (const l of LESSONS)
      for (const p of l.presets) {
        const scene = SCENES.find((s) => s.path === p.route)!;
        const query = parseHash(presetHref(p, true)).query;
        expect(presetAskFor(scene.id, query), presetHref(p)).toBe(p.ask);
        expect(presetAskFor(scene.id, `${query}&theme=dark`), presetHref(p)).toBe(p.ask);
      }
    // other values, an extra parameter or another scene: not the preset
    expect(presetAskFor('texture', 'u=0.41&v=0.24&ask=1')).toBeNull();
    expect(presetAskFor('texture', 'u=0.4&v=0.24&wrap=clamp&ask=1')).toBeNull();
    expect(presetAskFor('ray-sphere', 'u=0.4&v=0.24&ask=1')).toBeNull();
  });

  it('the catalogue’s prediction prompts belong to real parts; every scene asks something', () => {
    for (const s of SCENES) {
      for (const part of Object.keys(s.predict ?? {})) expect(s.parts, s.id).toContain(part);
      expect(predictPrompt(s, null), s.id).toMatch(/\?/);
      // part= picks its own prompt; a part without one falls back to the first part's
      for (const part of s.parts)
        expect(predictPrompt(s, part)).toBe(s.predict?.[part] ?? predictPrompt(s, null));
    }
  });

  it('lists misconceptions for every scene', () => {
    expect(MISCONCEPTIONS.map((m) => m.route).sort()).toEqual(SCENES.map((s) => s.path).sort());
    for (const m of MISCONCEPTIONS) expect(m.items.length).toBeGreaterThanOrEqual(3);
  });
});
