/** What a host's `set` meets on a scene: the URL parser's problems, then the scene's own checks. */
import { describe, expect, it } from 'vitest';
import { validateSet } from '../../src/app/hostApi';
import { refusedValues } from '../../src/app/hostCheck';
import { parseParams, type ParamSchema, type ParamValues } from '../../src/kit/params';
import type { SceneId } from '../../src/kit/catalogue';
import { sceneCheck, sceneSchema } from '../e2e/sceneSchemas';

type Params = Record<string, unknown>;

/** The names of every problem a `set` of `params` on the scene opened with `query` meets (both checks). */
export async function setProblems(id: SceneId, params: Params, query = ''): Promise<string[]> {
  const schema: ParamSchema = await sceneSchema(id);
  const current = parseParams(schema, query).values as ParamValues<ParamSchema>;
  const r = validateSet(schema, params);
  if (!r.ok) return r.problems.map((p) => p.name);
  return (await refusedValues(schema, current, r.patch, await sceneCheck(id))).map((p) => p.name);
}

/**
 * A scene's own fallbacks, as a host meets them: each `refused` set (on the page opened with
 * `query`) fails naming the parameter; each `accepted` one passes.
 */
export function hostSetCases(
  id: SceneId,
  cases: { refused: [Params, string, string?][]; accepted: [Params, string?][] },
): void {
  describe(`set on ${id}: values the scene would replace are refused`, () => {
    it.each(cases.refused)('%j refused, naming %s (page: %s)', async (params, name, query) => {
      expect(await setProblems(id, params, query)).toContain(name);
    });
    it.each(cases.accepted)('%j accepted (page: %s)', async (params, query) => {
      expect(await setProblems(id, params, query)).toEqual([]);
    });
  });
}
