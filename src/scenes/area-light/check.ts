/**
 * The values this scene would not use as given (SceneModule.checkValues): the problems buildModel,
 * the code the scene runs, reports when it replaces a value by a safe one.
 */
import type { ParamProblem } from '../../kit/params';
import { buildModel } from './model';
import type { AreaLightParams } from './params';

export function checkValues(params: AreaLightParams): ParamProblem[] {
  return buildModel(params).problems;
}
