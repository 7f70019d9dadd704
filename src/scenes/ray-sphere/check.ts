/**
 * The values this scene would not use as given (SceneModule.checkValues): checkInputs, the code the
 * scene runs, replaces them by safe ones; a parameter whose used value differs is named, with the
 * model's own message.
 */
import type { ParamProblem } from '../../kit/params';
import { checkInputs } from './model';
import type { RaySphereParams } from './params';

const same = (a: readonly number[], b: readonly number[]) =>
  a.length === b.length && a.every((x, i) => Object.is(x, b[i]));

const WORDS: Record<'o' | 'd' | 'c' | 'r', RegExp> = {
  o: /origin o/,
  d: /direction d/,
  c: /centre C/,
  r: /radius/,
};

export function checkValues(params: RaySphereParams): ParamProblem[] {
  const used = checkInputs(params);
  const why = (name: keyof typeof WORDS, value: string) =>
    used.problems.find((t) => WORDS[name].test(t)) ?? `is not usable here; the scene would use ${value}.`;
  const out: ParamProblem[] = [];
  for (const name of ['o', 'd', 'c'] as const)
    if (!same(params[name], used[name])) out.push({ name, message: why(name, used[name].join(',')) });
  if (!Object.is(params.r, used.r)) out.push({ name: 'r', message: why('r', String(used.r)) });
  return out;
}
