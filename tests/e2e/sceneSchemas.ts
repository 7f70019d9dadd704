/**
 * Every scene's URL schema, read from the scene's own params.ts through the catalogue
 * (src/kit/catalogue.ts), so browser tests iterate the scenes without listing them.
 */
import { SCENES, type SceneId } from '../../src/kit/catalogue';
import type { ParamSchema, ParamSpec } from '../../src/kit/params';
import type { SceneCheck } from '../../src/kit/scene';

export { SCENES };

/** The URL schema of a scene (its params.ts `schema`). */
export async function sceneSchema(id: SceneId): Promise<ParamSchema> {
  const mod = (await import(`../../src/scenes/${id}/params.ts`)) as { schema: ParamSchema };
  return mod.schema;
}

/** A scene's parameters, by name and kind. */
export async function sceneParams(id: SceneId): Promise<{ name: string; kind: string }[]> {
  return Object.entries(await sceneSchema(id)).map(([name, spec]) => ({ name, kind: spec.kind }));
}

/**
 * The query that sets every count of a scene to the largest its schema allows (or to `fraction`
 * of it): each integer parameter but the seed and the timeline's position t.
 */
export async function maxCountsQuery(id: SceneId, fraction = 1): Promise<string> {
  const out: string[] = [];
  for (const [name, spec] of Object.entries(await sceneSchema(id)))
    if (spec.kind === 'number' && spec.integer && name !== 'seed' && name !== 't' && spec.max !== undefined)
      out.push(`${name}=${Math.max(spec.min ?? 1, Math.round(spec.max * fraction))}`);
  return out.join('&');
}

/**
 * Values a host's `set` must refuse for a parameter, from its spec alone: the wrong type, and where
 * the spec bounds it, a value out of range, not whole, too long or of the wrong length.
 */
export function invalidValues(spec: ParamSpec): unknown[] {
  switch (spec.kind) {
    case 'number':
      return [
        'abc',
        true,
        [1],
        ...(spec.max !== undefined ? [spec.max + Math.max(1, Math.abs(spec.max))] : []),
        ...(spec.min !== undefined ? [spec.min - Math.max(1, Math.abs(spec.min))] : []),
        ...(spec.integer ? [(spec.min ?? 0) + 0.5] : []),
      ];
    case 'enum':
      return ['not-a-value', 7, ` ${spec.default}`];
    case 'string':
      return [[1, 2], ...(spec.maxLength !== undefined ? ['x'.repeat(spec.maxLength + 1)] : [])];
    case 'bool':
      return ['yes', 2, [1]];
    case 'vec3':
      return [[1, 2], 'abc', ...(spec.max !== undefined ? [[spec.max * 2 + 1, 0, 0]] : [])];
    case 'list':
      return [
        'abc',
        Array.from({ length: spec.maxItems + 1 }, () => 0),
        ...(spec.max !== undefined ? [[spec.max * 2 + 1]] : []),
      ];
  }
}

/** A scene's own check of values (its module's checkValues), if it has one. */
export async function sceneCheck(id: SceneId): Promise<SceneCheck | undefined> {
  const mod = (await import(`../../src/scenes/${id}/check.ts`)) as { checkValues?: SceneCheck };
  return mod.checkValues;
}
