/**
 * The values this scene would not use as given (SceneModule.checkValues): the problems that
 * checkInputs, the code the scene runs, reports when it replaces a value by a safe one.
 */
import type { ParamProblem } from '../../kit/params';
import { checkInputs } from './inputs';
import type { RaySphereParams } from './params';

export function checkValues(params: RaySphereParams): ParamProblem[] {
  return checkInputs(params).problems;
}
