/**
 * The URL reference (docs/urls.md) written from the parameter schemas themselves, so the page cannot
 * drift from what the parser accepts: tests/docs/urls.test.ts regenerates it and fails when the file
 * differs (`npm run docs:urls` rewrites it). Pure: schemas in, Markdown out.
 */
import type { ParamSchema, ParamSpec } from '../src/kit/params';

/** One route and the schema its parameters follow. */
export interface RouteSchema {
  route: string;
  title: string;
  schema: ParamSchema;
}

const code = (s: string) => '`' + s.replace(/`/g, 'ˋ') + '`';
const cell = (s: string) => s.replace(/\|/g, '\\|').replace(/\n/g, ' ');

/** "0 … 1", "≥ 1", "≤ 7" or "" for a number's range. */
function range(min: number | undefined, max: number | undefined): string {
  if (min !== undefined && max !== undefined) return `${min} … ${max}`;
  if (min !== undefined) return `≥ ${min}`;
  if (max !== undefined) return `≤ ${max}`;
  return '';
}

/** What a value of this parameter may be, in words. */
export function allowedText(spec: ParamSpec): string {
  switch (spec.kind) {
    case 'number': {
      const r = range(spec.min, spec.max);
      return [spec.integer ? 'integer' : 'number', r].filter(Boolean).join(', ');
    }
    case 'enum': {
      const aliases = Object.entries(spec.aliases ?? {});
      const main = spec.values.map(code).join(' · ');
      return aliases.length
        ? `${main} (also ${aliases.map(([a, v]) => `${code(a)} = ${code(v)}`).join(', ')})`
        : main;
    }
    case 'string': {
      const parts = [`text, at most ${spec.maxLength ?? 'any'} characters`];
      if (spec.expression) parts.push(`an expression in ${spec.expression.map(code).join(', ')}`);
      return parts.join('; ');
    }
    case 'bool':
      return '`1` or `0`';
    case 'vec3': {
      const r = range(spec.min, spec.max);
      return `three numbers ${code('x,y,z')}${r ? `, each ${r}` : ''}`;
    }
    case 'list': {
      const n =
        spec.minItems !== undefined && spec.minItems === spec.maxItems
          ? `${spec.maxItems}`
          : `${spec.minItems ?? 1} … ${spec.maxItems}`;
      const r = range(spec.min, spec.max);
      return `comma list of ${n} numbers${r ? `, each ${r}` : ''}`;
    }
  }
}

/** The default as a link would spell it. */
export function defaultText(spec: ParamSpec): string {
  const d = spec.default;
  if (d === null) return 'none';
  if (typeof d === 'boolean') return d ? '`1`' : '`0`';
  if (Array.isArray(d)) return code(d.join(','));
  return code(String(d));
}

/** The Markdown table of one route's parameters. */
export function routeTable(r: RouteSchema): string {
  const rows = Object.entries(r.schema).map(
    ([name, spec]) =>
      `| ${code(name)} | ${cell(spec.label ?? '')} | ${cell(defaultText(spec))} | ${cell(allowedText(spec))} |`,
  );
  return [
    `### ${code('#' + r.route)}: ${r.title}`,
    '',
    '| parameter | meaning | default | allowed |',
    '|---|---|---|---|',
    ...rows,
  ].join('\n');
}

/** The generated part of docs/urls.md: every route's table, in the order given. */
export function urlReference(routes: readonly RouteSchema[]): string {
  return routes.map(routeTable).join('\n\n') + '\n';
}

export const BEGIN = '<!-- generated from the schemas: begin (npm run docs:urls rewrites this part) -->';
export const END = '<!-- generated from the schemas: end -->';

/** `doc` with the text between the markers replaced by `generated`. Throws when a marker is missing. */
export function spliceGenerated(doc: string, generated: string): string {
  const a = doc.indexOf(BEGIN);
  const b = doc.indexOf(END);
  if (a < 0 || b < a) throw new Error('docs/urls.md has lost its generated-part markers');
  return `${doc.slice(0, a + BEGIN.length)}\n\n${generated}\n${doc.slice(b)}`;
}
