/**
 * A host's `set` fails, applying nothing, for every value the scene would not use as given: the
 * values its URL parser rejects (for every parameter of every scene, from the parameter's spec)
 * and the values the scene would replace by a fallback ("using … instead" on the page), decided
 * by the scene's own model checks (SceneModule.checkValues) and the expression compiler, as on the
 * page. The scenes come from the catalogue; the fallbacks each scene refuses are tested with the
 * scene (tests/scenes/<id>/hostSet.test.ts).
 */
import { describe, expect, it } from 'vitest';
import { parseParams } from '../../src/kit/params';
import { SCENES, invalidValues, sceneSchema } from '../e2e/sceneSchemas';
import { setProblems } from './hostSet';

describe.each(SCENES.map((s) => s.id))('set on %s', (id) => {
  it('refuses every parameter’s invalid values, naming the parameter', async () => {
    const schema = await sceneSchema(id);
    for (const [name, spec] of Object.entries(schema))
      for (const bad of invalidValues(spec))
        expect(await setProblems(id, { [name]: bad }), `${name} = ${JSON.stringify(bad)}`).toContain(name);
  });
  it('accepts every parameter at its default value, alone and all together', async () => {
    const schema = await sceneSchema(id);
    // (a list whose default is "none given" has no value to send)
    const defaults = Object.fromEntries(
      Object.entries(parseParams(schema, '').values as Record<string, unknown>).filter(([, v]) => v !== null),
    );
    expect(await setProblems(id, defaults)).toEqual([]);
    for (const [name, v] of Object.entries(defaults))
      expect(await setProblems(id, { [name]: v }), name).toEqual([]);
  });
});
