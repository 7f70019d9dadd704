/**
 * A host's `set` fails, applying nothing, for every value the scene would replace by a fallback
 * ("using … instead" on the page), not only for values the URL parser rejects: the scenes' own
 * model checks (SceneModule.checkValues) and the expression compiler decide, as on the page.
 */
import { describe, expect, it } from 'vitest';
import { validateSet } from '../../src/app/hostApi';
import { refusedValues } from '../../src/app/hostCheck';
import { parseParams, type ParamSchema, type ParamValues } from '../../src/kit/params';
import type { SceneCheck } from '../../src/kit/scene';
import * as hemisphere from '../../src/scenes/hemisphere/params';
import * as monteCarlo from '../../src/scenes/monte-carlo/params';
import * as raySphere from '../../src/scenes/ray-sphere/params';
import * as areaLight from '../../src/scenes/area-light/params';
import * as texture from '../../src/scenes/texture/params';
import { checkValues as hemiCheck } from '../../src/scenes/hemisphere/check';
import { checkValues as mcCheck } from '../../src/scenes/monte-carlo/check';
import { checkValues as rsCheck } from '../../src/scenes/ray-sphere/check';
import { checkValues as alCheck } from '../../src/scenes/area-light/check';
import { checkValues as txCheck } from '../../src/scenes/texture/check';

const SCENES: Record<string, { schema: ParamSchema; check: SceneCheck }> = {
  hemisphere: { schema: hemisphere.schema, check: hemiCheck as SceneCheck },
  'monte-carlo': { schema: monteCarlo.schema, check: mcCheck as SceneCheck },
  'ray-sphere': { schema: raySphere.schema, check: rsCheck as SceneCheck },
  'area-light': { schema: areaLight.schema, check: alCheck as SceneCheck },
  texture: { schema: texture.schema, check: txCheck as SceneCheck },
};

/** Every problem a `set` of `params` on the scene opened with `query` meets (both checks). */
async function setProblems(id: string, params: Record<string, unknown>, query = ''): Promise<string[]> {
  const { schema, check } = SCENES[id];
  const current = parseParams(schema, query).values as ParamValues<ParamSchema>;
  const r = validateSet(schema, params);
  if (!r.ok) return r.problems.map((p) => p.name);
  return (await refusedValues(schema, current, r.patch, check)).map((p) => p.name);
}

describe('set refuses what the scene would replace', () => {
  it.each([
    ['monte-carlo', { a: 1, b: 1 }, 'b'],
    ['monte-carlo', { a: 3 }, 'b'],
    ['ray-sphere', { d: [0, 0, 0] }, 'd'],
    ['ray-sphere', { d: [1e-200, 0, 0] }, 'd'],
    ['area-light', { ls: [0, 0] }, 'ls'],
    ['area-light', { ls: [1e-160, 1e-160] }, 'ls'],
    ['texture', { grid: '1,2,3;4' }, 'grid'],
    ['texture', { grid: '' }, 'grid'],
    ['hemisphere', { lobe: 'custom', pdf: '-1' }, 'pdf'],
    ['hemisphere', { lobe: 'custom', pdf: 'import(1)' }, 'pdf'],
    ['hemisphere', { pdf: 'import(1)' }, 'pdf'],
    ['hemisphere', { f: 'cos(theta' }, 'f'],
    ['monte-carlo', { f: 'x +* 2' }, 'f'],
  ] as [string, Record<string, unknown>, string][])('%s %j', async (id, params, name) => {
    expect(await setProblems(id, params)).toContain(name);
  });

  it('a page already on custom refuses a bad density set on its own', async () => {
    expect(await setProblems('hemisphere', { pdf: '0*theta' }, 'lobe=custom')).toEqual(['pdf']);
  });

  it.each([
    ['monte-carlo', { a: 0.5, b: 1.5 }],
    ['ray-sphere', { d: [0, 1, 0], r: 2 }],
    ['area-light', { ls: [2, 0.5] }],
    ['texture', { grid: '1,2;3,4' }],
    ['hemisphere', { lobe: 'custom', pdf: 'cos(theta)' }],
    ['hemisphere', { f: 'sin(theta)*cos(phi)^2' }],
  ] as [string, Record<string, unknown>][])('accepts usable values: %s %j', async (id, params) => {
    expect(await setProblems(id, params)).toEqual([]);
  });

  it('a fallback the page already shows does not block an unrelated set', async () => {
    // the link opened with a = b (the page says so); setting n alone changes nothing about that
    expect(await setProblems('monte-carlo', { n: 64 }, 'a=1&b=1')).toEqual([]);
    // but a set that keeps the limits unusable in a new way is refused
    expect(await setProblems('monte-carlo', { b: 0.5 }, 'a=1&b=1')).toEqual(['b']);
  });
});
