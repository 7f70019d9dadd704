/**
 * The render lab's settings, bound to its URL parameters: the preset and the estimator first, then
 * the image, the exam scene's objects and the camera (the vectors as number boxes per component).
 */
import type { ReactNode } from 'react';
import { bindControls } from '../../../ui/paramControls';
import { NumberField } from '../../../ui';
import { STRATEGIES } from '../../../core/render/directLight';
import { schema, type RenderParams } from '../params';

type Vec3Name = 'lc' | 'c';

function VectorFields({
  name,
  label,
  params,
  set,
}: {
  name: Vec3Name;
  label: string;
  params: RenderParams;
  set: (p: Partial<RenderParams>) => void;
}) {
  const v = params[name];
  return (
    <fieldset className="render-vector">
      <legend>{label}</legend>
      {(['x', 'y', 'z'] as const).map((axis, k) => (
        <NumberField
          key={axis}
          label={axis}
          value={v[k]}
          step={0.1}
          onChange={(x) => {
            const next: [number, number, number] = [v[0], v[1], v[2]];
            next[k] = x;
            set({ [name]: next } as Partial<RenderParams>);
          }}
        />
      ))}
    </fieldset>
  );
}

export function Controls({
  params,
  set,
}: {
  params: RenderParams;
  set: (p: Partial<RenderParams>) => void;
}): ReactNode {
  const b = bindControls(schema, params, set);
  const exam = params.scene === 'exam';
  return (
    <div className="render-controls">
      {b.select('scene', 'Scene', [
        { value: 'exam', label: 'The exam’s objects' },
        { value: 'veach', label: 'Veach’s four plates' },
        { value: 'furnace', label: 'White furnace' },
      ])}
      {b.select(
        'renderer',
        'Renderer',
        [
          { value: 'gpu', label: 'GPU: WebGL2 fragment shader, float32' },
          { value: 'cpu', label: 'CPU: the core in workers, float64' },
        ],
        { testId: 'set-renderer' },
      )}
      {b.select(
        'strategy',
        'Direct-light strategy',
        STRATEGIES.map((s) => ({ value: s, label: s })),
      )}
      {b.select('bias', 'Biased variant (the t-test should catch it)', [
        { value: 'none', label: 'none: the correct estimator' },
        { value: 'no-cos-l', label: 'area sampling without cos θ_l' },
        { value: 'clamp', label: 'every term clamped at 0.5' },
      ])}
      {b.slider('bounces', 'Bounces (1 = direct light only)', { testId: 'set-bounces' })}
      {b.slider('spp', 'Samples per pixel', { log: true, max: 4096, testId: 'set-spp' })}
      {b.slider('res', 'Image side (pixels)', { step: 16, testId: 'set-res' })}
      {b.number('seed', 'Seed', { testId: 'set-seed' })}
      {b.number('pn', 'Inspector samples', { testId: 'set-pn' })}
      {b.toggle('play', 'Render', { testId: 'set-play' })}
      {exam ? (
        <>
          {b.slider('rho', 'Floor albedo ρ', { testId: 'set-rho' })}
          <VectorFields name="lc" label="Light centre" params={params} set={set} />
          {b.slider('tilt', 'Light tilt (degrees)', { min: -90, max: 90, testId: 'set-tilt' })}
          {b.slider('L', 'Light radiance L', { min: 0, max: 20, testId: 'set-L' })}
          <VectorFields name="c" label="Sphere centre" params={params} set={set} />
          {b.slider('r', 'Sphere radius r', { min: 0.05, max: 3, testId: 'set-r' })}
          {b.select('filter', 'Texture filter', [
            { value: 'bilinear', label: 'bilinear' },
            { value: 'nearest', label: 'nearest' },
          ])}
        </>
      ) : null}
    </div>
  );
}
