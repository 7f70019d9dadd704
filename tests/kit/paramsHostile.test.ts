/** Hostile link parameters: prototype names, '+' in expressions, broken escapes. */
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { parseParams, serializeParams, type ParamSchema } from '../../src/kit/params';

const schema = {
  mode: { kind: 'enum', default: 'a', values: ['a', 'b'], aliases: { bee: 'b' } },
  noAlias: { kind: 'enum', default: 'x', values: ['x', 'y'] },
  n: { kind: 'number', default: 1, min: 0, max: 10 },
  f: { kind: 'string', default: 'x', maxLength: 400, expression: ['x'] },
  label: { kind: 'string', default: '' },
  on: { kind: 'bool', default: false },
  v: { kind: 'vec3', default: [0, 0, 1] },
  l: { kind: 'list', default: null, maxItems: 4 },
} as const satisfies ParamSchema;

const PROTO_NAMES = [...Object.getOwnPropertyNames(Object.prototype), 'prototype', '__defineGetter__'];

describe('parseParams with hostile keys and values', () => {
  it('property: a prototype name as any enum value falls back to the default with a notice naming the parameter', () => {
    fc.assert(
      fc.property(fc.constantFrom('mode', 'noAlias'), fc.constantFrom(...PROTO_NAMES), (name, value) => {
        const r = parseParams(schema, `${name}=${encodeURIComponent(value)}`);
        expect(r.values[name]).toBe(schema[name].default);
        expect(r.problems.map((p) => p.name)).toContain(name);
        expect(typeof r.values[name]).toBe('string');
        // the next write does not carry a function's source
        expect(serializeParams(schema, r.values)).toBe('');
      }),
      { seed: 1, numRuns: 100 },
    );
  });

  it('property: arbitrary keys (prototype names included) never change a value or the prototype', () => {
    fc.assert(
      fc.property(
        fc.array(
          fc.tuple(
            fc.oneof(fc.constantFrom(...PROTO_NAMES), fc.string({ maxLength: 12 })),
            fc.string({ maxLength: 12 }),
          ),
          { maxLength: 8 },
        ),
        (pairs) => {
          const q = pairs.map(([k, v]) => `${encodeURIComponent(k)}=${encodeURIComponent(v)}`).join('&');
          const r = parseParams(schema, q);
          for (const [k] of pairs) {
            if (!Object.hasOwn(schema, k)) expect(Object.hasOwn(r.values, k)).toBe(false);
          }
          expect(Object.getPrototypeOf(r.values)).toBe(Object.prototype);
          expect(({} as Record<string, unknown>).polluted).toBeUndefined();
          for (const [name, spec] of Object.entries(schema)) {
            const v = (r.values as Record<string, unknown>)[name];
            if (spec.kind === 'enum') expect(spec.values as readonly string[]).toContain(v);
            if (spec.kind === 'number') expect(Number.isFinite(v)).toBe(true);
          }
        },
      ),
      { seed: 2, numRuns: 300 },
    );
  });

  it('keeps a literal + in an expression parameter and says so; other strings read + as a space', () => {
    const r = parseParams(schema, 'f=(x+3)^2&label=a+b');
    expect(r.values.f).toBe('(x+3)^2');
    expect(r.values.label).toBe('a b');
    const note = r.problems.find((p) => p.name === 'f');
    expect(note?.message).toMatch(/plus/);
    // our own links encode + as %2B: no notice
    const own = parseParams(schema, serializeParams(schema, { f: 'x + 1' }));
    expect(own.values.f).toBe('x + 1');
    expect(own.problems).toEqual([]);
  });

  it('broken percent-escapes, NaN, ±Infinity, 1e400 and huge values are named and fall back', () => {
    const big = 'x'.repeat(100_000);
    const r = parseParams(schema, `n=NaN&mode=%E0%A4%A&v=1,2&l=1e400&f=${big}&on=%ZZ`);
    const names = r.problems.map((p) => p.name);
    for (const n of ['n', 'mode', 'v', 'l', 'f', 'on']) expect(names).toContain(n);
    expect(r.values.n).toBe(1);
    expect(r.values.f).toBe('x');
    for (const q of ['n=Infinity', 'n=-Infinity', 'n=1e400', 'n=', 'n=%', 'n=0x10']) {
      const s = parseParams(schema, q);
      expect(s.values.n).toBe(1);
      expect(s.problems[0]?.name).toBe('n');
    }
  });
});
