/**
 * Every scene's own URL schema against the hostile values a link may carry (prototype names, empty,
 * NaN, ±Infinity, 1e400, 100k characters, unicode and RTL marks, broken percent-escapes, wrong
 * arity, deeply nested calls), all of a scene's parameters set to the same value at once: every
 * parameter that is not free text and cannot use the value is named, and falls back to a value of
 * its own kind. The browser test (tests/e2e/hostile.spec.ts) checks that the page shows the notice
 * and keeps working.
 */
import { describe, expect, it } from 'vitest';
import { SCENES } from '../../src/kit/catalogue';
import { parseParams, type ParamSchema } from '../../src/kit/params';

const NESTED = `${'exp('.repeat(60)}x${')'.repeat(60)}`;
/** [label, raw text put into the query as is (already URL-encoded where needed)]. */
const CORPUS: [string, string][] = [
  ['__proto__', '__proto__'],
  ['constructor', 'constructor'],
  ['toString', 'toString'],
  ['valueOf', 'valueOf'],
  ['hasOwnProperty', 'hasOwnProperty'],
  ['empty', ''],
  ['NaN', 'NaN'],
  ['Infinity', 'Infinity'],
  ['-Infinity', '-Infinity'],
  ['1e400', '1e400'],
  ['100k characters', 'x'.repeat(100_000)],
  ['unicode and RTL marks', encodeURIComponent('\u202Eθ\u200F😀\u200E')],
  ['broken percent-escapes', '%E0%A4%A%ZZ%'],
  ['wrong arity', '1,2'],
  ['deeply nested calls', encodeURIComponent(NESTED)],
];

describe.each(SCENES.map((s) => s.id))('%s: every parameter × every hostile value', (id) => {
  it.each(CORPUS)('%s: each parameter that cannot use it is named and falls back', async (_label, raw) => {
    const { schema } = (await import(`../../src/scenes/${id}/params.ts`)) as { schema: ParamSchema };
    const names = Object.keys(schema);
    const r = parseParams(schema, names.map((n) => `${n}=${raw}`).join('&'));
    const named = new Set(r.problems.map((p) => p.name));
    for (const [name, spec] of Object.entries(schema)) {
      // a list takes '' as its default and '1,2' as two numbers: those are usable
      const usable = spec.kind === 'string' || (spec.kind === 'list' && (raw === '' || raw === '1,2'));
      if (!usable) expect(named.has(name), `${id}: ${name}=${_label} is named`).toBe(true);
      const v = (r.values as Record<string, unknown>)[name];
      if (spec.kind === 'number') expect(Number.isFinite(v), `${id}: ${name} is a finite number`).toBe(true);
      if (spec.kind === 'enum') expect(spec.values, `${id}: ${name} is one of its values`).toContain(v);
      if (spec.kind === 'bool') expect(typeof v, `${id}: ${name} is a boolean`).toBe('boolean');
    }
  });
});
