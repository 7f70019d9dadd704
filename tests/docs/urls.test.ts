/**
 * docs/urls.md against the schemas: the generated part must equal what scripts/urlReference.ts writes
 * from every route's schema today. `npm run docs:urls` (UPDATE_DOCS=1) rewrites the file instead.
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { LABS, SCENES } from '../../src/kit/catalogue';
import type { ParamSchema } from '../../src/kit/params';
import {
  allowedText,
  BEGIN,
  END,
  spliceGenerated,
  urlReference,
  type RouteSchema,
} from '../../scripts/urlReference';

const DOC = new URL('../../docs/urls.md', import.meta.url);

async function routes(): Promise<RouteSchema[]> {
  const out: RouteSchema[] = [];
  for (const s of [...SCENES, ...LABS]) {
    const mod = (await import(`../../src/scenes/${s.id}/params.ts`)) as { schema: ParamSchema };
    out.push({ route: s.path, title: s.title, schema: mod.schema });
  }
  return out;
}

describe('the URL reference', () => {
  it('docs/urls.md holds exactly what the schemas generate', async () => {
    const doc = readFileSync(DOC, 'utf8');
    const want = spliceGenerated(doc, urlReference(await routes()));
    if (process.env.UPDATE_DOCS === '1') writeFileSync(DOC, want);
    else expect(doc, 'docs/urls.md is out of date: run npm run docs:urls').toBe(want);
  });

  it('names every parameter of every scene', async () => {
    const doc = readFileSync(DOC, 'utf8');
    const generated = doc.slice(doc.indexOf(BEGIN), doc.indexOf(END));
    for (const r of await routes())
      for (const name of Object.keys(r.schema)) expect(generated).toContain(`| \`${name}\` |`);
  });

  it('describes each kind of value in words', () => {
    expect(allowedText({ kind: 'number', default: 1, min: 0, max: 7, integer: true })).toBe('integer, 0 … 7');
    expect(allowedText({ kind: 'enum', default: 'a', values: ['a', 'b'], aliases: { x: 'a' } })).toBe(
      '`a` · `b` (also `x` = `a`)',
    );
    expect(allowedText({ kind: 'list', default: null, minItems: 2, maxItems: 2, min: 0 })).toBe(
      'comma list of 2 numbers, each ≥ 0',
    );
    expect(allowedText({ kind: 'string', default: '', maxLength: 9, expression: ['x'] })).toBe(
      'text, at most 9 characters; an expression in `x`',
    );
  });

  it('refuses a page that lost its markers', () => {
    expect(() => spliceGenerated('no markers here', 'x')).toThrow(/markers/);
  });
});
