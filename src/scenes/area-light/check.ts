/**
 * The values this scene would not use as given (SceneModule.checkValues): buildModel, the code the
 * scene runs, replaces them by safe ones; a parameter whose used value differs from the given one
 * is named, with the model's own message.
 */
import type { ParamProblem } from '../../kit/params';
import { buildModel } from './model';
import type { AreaLightParams } from './params';

const same = (a: readonly number[], b: readonly number[]) =>
  a.length === b.length && a.every((x, i) => Object.is(x, b[i]));

export function checkValues(params: AreaLightParams): ParamProblem[] {
  const m = buildModel(params);
  const errors = m.messages.filter((x) => x.kind === 'error').map((x) => x.text);
  const why = (re: RegExp, used: string) =>
    errors.find((t) => re.test(t)) ?? `is not usable here; the scene would use ${used}.`;
  const out: ParamProblem[] = [];
  if (!same(params.p, m.p)) out.push({ name: 'p', message: why(/shading point/i, m.p.join(',')) });
  if (!same(params.lc, m.lc))
    out.push({ name: 'lc', message: why(/light centre|the light to/i, m.lc.join(',')) });
  if (!same(params.ls ?? [], [m.w, m.h]))
    out.push({ name: 'ls', message: why(/light of size/i, `${m.w},${m.h}`) });
  if (!Object.is(params.tilt, m.tilt))
    out.push({ name: 'tilt', message: why(/the light to/i, String(m.tilt)) });
  if (!Object.is(params.L, m.L)) out.push({ name: 'L', message: why(/^$/, String(m.L)) });
  if (!Object.is(params.rho, m.rho)) out.push({ name: 'rho', message: why(/^$/, String(m.rho)) });
  return out;
}
