/**
 * The values this page would not use as given (SceneModule.checkValues): the problems of
 * buildRenderModel, the code the page runs.
 */
import type { ParamProblem } from '../../kit/params';
import { buildRenderModel } from './model';
import type { RenderParams } from './params';

export function checkValues(params: RenderParams): ParamProblem[] {
  return buildRenderModel(params).problems;
}
