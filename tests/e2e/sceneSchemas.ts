/**
 * Every scene's URL schema, read from the scene's own params.ts through the catalogue
 * (src/kit/catalogue.ts), so browser tests iterate the scenes without listing them.
 */
import { SCENES, type SceneId } from '../../src/kit/catalogue';
import type { ParamSchema } from '../../src/kit/params';

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
 * The query that sets every count of a scene to the largest its schema allows: each integer
 * parameter but the seed and the timeline's position t.
 */
export async function maxCountsQuery(id: SceneId): Promise<string> {
  const out: string[] = [];
  for (const [name, spec] of Object.entries(await sceneSchema(id)))
    if (spec.kind === 'number' && spec.integer && name !== 'seed' && name !== 't' && spec.max !== undefined)
      out.push(`${name}=${spec.max}`);
  return out.join('&');
}
