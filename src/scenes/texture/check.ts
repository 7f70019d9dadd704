/**
 * The values this scene would not use as given (SceneModule.checkValues): a `grid` text that
 * resolveGrid, the code the scene runs, cannot read (the scene then shows the exam's grid).
 */
import type { ParamProblem } from '../../kit/params';
import { resolveGrid } from './model';
import type { ParamValues } from '../../kit/params';
import type { TextureSchema } from './params';

type TextureParams = ParamValues<TextureSchema>;

export function checkValues(params: TextureParams): ParamProblem[] {
  const src = resolveGrid(params);
  return src.error ? [{ name: 'grid', message: `${src.error} (the scene would use the exam’s grid)` }] : [];
}
