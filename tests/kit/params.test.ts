import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  parseNumber,
  parseParams,
  serializeParams,
  defaultValues,
  type ParamSchema,
} from '../../src/kit/params';

const schema = {
  u: { kind: 'number', default: 0.4, min: -4, max: 4 },
  n: { kind: 'number', default: 1000, min: 1, max: 1e7, integer: true },
  seed: { kind: 'number', default: 1, min: 0, max: 4294967295, integer: true },
  lobe: {
    kind: 'enum',
    default: 'exam',
    values: ['exam', 'uniform', 'cosine'],
    aliases: { lambert: 'cosine' },
  },
  f: { kind: 'string', default: 'cos(theta)', maxLength: 40 },
  vflip: { kind: 'bool', default: false },
  o: { kind: 'vec3', default: [0, 0, -5], min: -1e6, max: 1e6 },
  samples: { kind: 'list', default: null, maxItems: 8, min: -10, max: 10 },
} as const satisfies ParamSchema;

const names = (q: string) => parseParams(schema, q).problems.map((p) => p.name);

describe('parseNumber', () => {
  it('accepts plain decimals and scientific notation only', () => {
    expect(parseNumber('0.4')).toBe(0.4);
    expect(parseNumber(' -3e2 ')).toBe(-300);
    expect(parseNumber('.5')).toBe(0.5);
    for (const bad of [
      '',
      ' ',
      'NaN',
      'Infinity',
      '-Infinity',
      '1e400',
      '0x10',
      '1,5',
      '1.2.3',
      '٣',
      '１',
      '1e',
      'e5',
      '--1',
    ])
      expect(parseNumber(bad), bad).toBeNull();
  });
});

describe('parseParams', () => {
  it('gives the defaults for an empty query, with no problems', () => {
    for (const q of ['', '?', '&&&', '?&']) {
      const r = parseParams(schema, q);
      expect(r.values).toEqual(defaultValues(schema));
      expect(r.problems).toEqual([]);
    }
  });

  it('parses valid values of every kind', () => {
    const r = parseParams(
      schema,
      '?u=0.25&n=64&seed=4294967295&lobe=uniform&f=sin(phi)&vflip=1&o=1,2,3&samples=1.16,1.98',
    );
    expect(r.problems).toEqual([]);
    expect(r.values).toEqual({
      u: 0.25,
      n: 64,
      seed: 4294967295,
      lobe: 'uniform',
      f: 'sin(phi)',
      vflip: true,
      o: [1, 2, 3],
      samples: [1.16, 1.98],
    });
  });

  it('falls back to the default and names the parameter for NaN, Infinity, 1e400 and junk', () => {
    for (const v of ['NaN', 'Infinity', '-Infinity', '1e400', 'abc', '', '%E2%88%9E']) {
      const r = parseParams(schema, `u=${v}`);
      expect(r.values.u, v).toBe(0.4);
      expect(names(`u=${v}`), v).toEqual(['u']);
    }
  });

  it('clamps out-of-range numbers and says so', () => {
    const r = parseParams(schema, 'u=99&n=-5&seed=5000000000');
    expect(r.values.u).toBe(4);
    expect(r.values.n).toBe(1);
    expect(r.values.seed).toBe(4294967295);
    expect(r.problems.map((p) => p.name).sort()).toEqual(['n', 'seed', 'u']);
    expect(r.problems.find((p) => p.name === 'u')!.message).toMatch(/outside/);
  });

  it('rounds integers and reports it', () => {
    const r = parseParams(schema, 'n=10.6');
    expect(r.values.n).toBe(11);
    expect(names('n=10.6')).toEqual(['n']);
  });

  it('resolves enum aliases and rejects unknown values', () => {
    expect(parseParams(schema, 'lobe=lambert').values.lobe).toBe('cosine');
    const r = parseParams(schema, 'lobe=<script>');
    expect(r.values.lobe).toBe('exam');
    expect(r.problems[0].name).toBe('lobe');
  });

  it('reports unknown and repeated keys, keeping the first of a repeat', () => {
    const r = parseParams(schema, 'u=0.1&u=0.2&zzz=1');
    expect(r.values.u).toBe(0.1);
    expect(r.problems.map((p) => p.name)).toEqual(['u', 'zzz']);
  });

  it('ignores the shell parameters', () => {
    expect(parseParams(schema, 'embed=1&present=1&theme=dark').problems).toEqual([]);
  });

  it('rejects huge lists, wrong vector lengths and over-long strings without throwing', () => {
    const huge = Array.from({ length: 100000 }, (_, i) => i % 10).join(',');
    const r = parseParams(schema, `samples=${huge}&o=1,2&f=${'x'.repeat(100)}`);
    expect(r.values.samples).toBeNull();
    expect(r.values.o).toEqual([0, 0, -5]);
    expect(r.values.f).toBe('cos(theta)');
    expect(r.problems.map((p) => p.name).sort()).toEqual(['f', 'o', 'samples']);
  });

  it('survives unicode and malformed percent-encoding', () => {
    const r = parseParams(schema, 'f=θ·φ&ü=1&u=%E0%A4%A&%%%=%');
    expect(r.values.f).toBe('θ·φ');
    expect(r.values.u).toBe(0.4);
    expect(r.problems.some((p) => p.name === 'u')).toBe(true);
  });

  it('caps the number of unknown-parameter messages', () => {
    const q = Array.from({ length: 500 }, (_, i) => `k${i}=1`).join('&');
    const r = parseParams(schema, q);
    expect(r.problems.length).toBeLessThanOrEqual(6);
    expect(r.problems.at(-1)!.message).toMatch(/495 more/);
  });

  it('never throws and always yields in-range values for arbitrary input (property)', () => {
    fc.assert(
      fc.property(fc.string({ unit: 'grapheme', maxLength: 200 }), (q) => {
        const r = parseParams(schema, q);
        return (
          Number.isFinite(r.values.u) &&
          r.values.u >= -4 &&
          r.values.u <= 4 &&
          Number.isInteger(r.values.n) &&
          r.values.n >= 1 &&
          r.values.n <= 1e7 &&
          ['exam', 'uniform', 'cosine'].includes(r.values.lobe) &&
          r.values.o.every((x) => Number.isFinite(x))
        );
      }),
      { numRuns: 2000 },
    );
  });

  it('round-trips through serializeParams (property)', () => {
    const arb = fc.record({
      u: fc.double({ min: -4, max: 4, noNaN: true }).map((x) => (Object.is(x, -0) ? 0 : x)),
      n: fc.integer({ min: 1, max: 1e7 }),
      seed: fc.integer({ min: 0, max: 4294967295 }),
      lobe: fc.constantFrom('exam', 'uniform', 'cosine'),
      f: fc.string({ maxLength: 40 }),
      vflip: fc.boolean(),
      o: fc
        .tuple(
          fc.double({ min: -1e6, max: 1e6, noNaN: true }),
          fc.double({ min: -1e6, max: 1e6, noNaN: true }),
          fc.double({ min: -1e6, max: 1e6, noNaN: true }),
        )
        .map((v) => v.map((x) => (Object.is(x, -0) ? 0 : x)) as [number, number, number]),
      samples: fc.option(
        fc.array(
          fc.double({ min: -10, max: 10, noNaN: true }).map((x) => (Object.is(x, -0) ? 0 : x)),
          { minLength: 1, maxLength: 8 },
        ),
        { nil: null },
      ),
    });
    fc.assert(
      fc.property(arb, (values) => {
        const q = serializeParams(schema, values);
        const r = parseParams(schema, q);
        expect(r.problems).toEqual([]);
        expect(r.values).toEqual(values);
      }),
      { numRuns: 500 },
    );
  });

  it('omits defaults and keeps extras when serialising', () => {
    expect(serializeParams(schema, defaultValues(schema))).toBe('');
    expect(
      serializeParams(schema, { ...defaultValues(schema), u: 0.5 }, { embed: '1', theme: undefined }),
    ).toBe('u=0.5&embed=1');
  });
});
