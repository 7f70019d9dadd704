/**
 * The values this scene would not use as given (SceneModule.checkValues): with lobe=custom, a typed
 * density that does not compile or is not a density (negative, zero, not finite) on the
 * hemisphere; the scene then samples nothing. The same compiler and tabulation the scene runs.
 */
import type { ParamProblem } from '../../kit/params';
import { compileThetaPhi } from './expr';
import { lobeFromParams } from './lobe';
import type { HemisphereParams } from './params';

export async function checkValues(params: HemisphereParams): Promise<ParamProblem[]> {
  if (params.lobe !== 'custom') return [];
  const c = await compileThetaPhi(params.pdf);
  if (!c.ok) return [{ name: 'pdf', message: `could not be used: ${c.message}` }];
  const { problem } = lobeFromParams('custom', params.exponent, c.fn);
  return problem ? [problem] : [];
}
