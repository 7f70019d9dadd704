/**
 * The values this scene would not use as given (SceneModule.checkValues): limits that checkLimits,
 * the code the scene runs, replaces by the exam's [0, 2].
 */
import type { ParamProblem } from '../../kit/params';
import { checkLimits } from './integral';
import type { ParamValues } from '../../kit/params';
import type { McSchema } from './params';

type MonteCarloParams = ParamValues<McSchema>;

export function checkValues(params: MonteCarloParams): ParamProblem[] {
  const { problem } = checkLimits(params.a, params.b);
  return problem ? [problem] : [];
}
