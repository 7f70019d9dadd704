/**
 * Q6(a)'s figure with the patch's own controls under it: the cross-section of the patch, its
 * perpendicular projection and the similar triangles, and sliders for where the patch sits on the
 * light, its side and its tilt.
 */
import type { ParamValues } from '../../../kit/params';
import { DescribedFigure } from '../../../ui';
import { bindControls } from '../../../ui/paramControls';
import type { PatchModel } from '../patch';
import { schema, type AreaLightParams } from '../params';
import { PatchFigure, patchFigureText } from './PatchFigure';

/** The patch's parameters: where it sits on the light, its side and its tilt. */
const PATCH_SCHEMA = { pu: schema.pu, pv: schema.pv, psize: schema.psize, ptilt: schema.ptilt };
export type PatchValues = ParamValues<typeof PATCH_SCHEMA>;

export function PatchPanel({
  patch,
  values,
  set,
}: {
  patch: PatchModel;
  values: PatchValues;
  set: (patch: Partial<AreaLightParams>) => void;
}) {
  const c = bindControls<typeof PATCH_SCHEMA>(PATCH_SCHEMA, values, set);
  return (
    <div className="al-6a-figure">
      <DescribedFigure
        label="Cross-section of Q6(a): the patch, its perpendicular projection and the similar triangles"
        description={patchFigureText(patch)}
        quiet
        testId="al-patch-described"
      >
        <PatchFigure patch={patch} />
      </DescribedFigure>
      <div className="al-patch-controls">
        {c.slider('pu', 'Patch position u on the light', { step: 0.01 })}
        {c.slider('pv', 'Patch position v on the light', { step: 0.01 })}
        {c.slider('psize', 'Patch side', { min: 0.001, log: true })}
        {c.slider('ptilt', 'Patch tilt (relative to the light)', { step: 1, unit: '°' })}
      </div>
    </div>
  );
}
