/**
 * The values this scene would not use as given (SceneModule.checkValues): the problems resolveGrid,
 * the code the scene runs, reports (a `grid` text it cannot read; the scene then shows the exam's
 * grid), each with what the scene does instead.
 */
import type { ParamProblem } from '../../kit/params';
import { resolveGrid } from './model';
import type { ParamValues } from '../../kit/params';
import type { TextureSchema } from './params';

type TextureParams = ParamValues<TextureSchema>;

export function checkValues(params: TextureParams): ParamProblem[] {
  return resolveGrid(params).problems.map(({ name, message }) => ({
    name,
    message: `${message} (the scene would use the exam’s grid)`,
  }));
}
