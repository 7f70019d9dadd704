/**
 * Each practice variant links to the scene that teaches it, in the variant's configuration: the
 * link's query is read by the scene's own schema (and its own check of values, where it has one)
 * with nothing refused, so the scene opens with no parameter notice and with exactly the
 * variant's values.
 */
import { describe, expect, it } from 'vitest';
import { QUESTIONS } from '../../src/practice/questions';
import { SCENES, type SceneId } from '../../src/kit/catalogue';
import { parseParams, type ParamSchema } from '../../src/kit/params';
import type { SceneCheck } from '../../src/kit/scene';

async function sceneOf(id: SceneId): Promise<{ schema: ParamSchema; check?: SceneCheck }> {
  const { schema } = (await import(`../../src/scenes/${id}/params.ts`)) as { schema: ParamSchema };
  const mods = import.meta.glob<{ checkValues?: SceneCheck }>('../../src/scenes/*/check.ts');
  const load = mods[`../../src/scenes/${id}/check.ts`];
  return { schema, check: load ? (await load()).checkValues : undefined };
}

describe('practice → scene links', () => {
  for (const q of QUESTIONS)
    it(`${q.id}: the scene link of a variant opens with every parameter used`, async () => {
      for (const seed of [1, 31, 4242]) {
        const v = q.generate(seed);
        const [path, query = ''] = v.sceneHref.replace(/^#/, '').split('?');
        const scene = SCENES.find((s) => s.path === path);
        expect(scene, v.sceneHref).toBeDefined();
        const { schema, check } = await sceneOf(scene!.id);
        const parsed = parseParams(schema, query);
        expect(parsed.problems, v.sceneHref).toEqual([]);
        if (check) expect(await check(parsed.values), v.sceneHref).toEqual([]);
        // every parameter the link names is the scene's, and was read (not left at its default)
        for (const [name] of new URLSearchParams(query)) expect(Object.hasOwn(schema, name), name).toBe(true);
      }
    });
});
