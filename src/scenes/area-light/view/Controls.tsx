/**
 * The control column of #/area-light: on the page, what the exam's figure and Q6(c) need (the
 * samples n); one click away, each in its fold, the strategy with the seed (the summary says both),
 * and the presets with the light, the floor and the shading point.
 */
import { memo } from 'react';
import { Panel, Slider } from '../../../ui';
import { Fold } from '../../../ui/Fold';
import { bindControls } from '../../../ui/paramControls';
import { VectorField } from '../../../ui/VectorField';
import { PRESETS, presetActive, schema, type AreaLightParams } from '../params';
import { STRATEGIES, STRATEGY_LABEL } from '../strategies';

type Set = (patch: Partial<AreaLightParams>) => void;

const STRATEGY_OPTIONS = STRATEGIES.map((s) => ({ value: s, label: STRATEGY_LABEL[s] }));
/** The light's two sides, the two entries of `ls`, and the range of their sliders. */
const SIDES = ['Width w', 'Height h'] as const;
const SIDE_RANGE = { min: 0, max: 10, step: 0.05 };

/** A vector parameter's three fields (test ids `<name>-x`, `-y`, `-z`), in the range the URL parser clamps it to. */
function VecField({
  name,
  label,
  params,
  set,
}: {
  name: 'p' | 'lc';
  label: string;
  params: AreaLightParams;
  set: Set;
}) {
  return (
    <VectorField
      label={label}
      value={params[name]}
      min={schema[name].min}
      max={schema[name].max}
      testIdPrefix={name}
      onChange={(v) => set({ [name]: v })}
    />
  );
}

export const Controls = memo(function Controls({
  params,
  set,
  reseeding,
  onToggleReseeding,
}: {
  params: AreaLightParams;
  set: Set;
  reseeding: boolean;
  onToggleReseeding: () => void;
}) {
  const c = bindControls(schema, params, set);
  const size = [params.ls?.[0] ?? 1, params.ls?.[1] ?? 1] as const;
  return (
    <>
      <Panel title="Sampling">{c.slider('n', 'Samples n', { log: true })}</Panel>
      <Fold
        name="sampling"
        className="al-fold"
        summary={
          <>
            Strategy: {STRATEGY_LABEL[params.strategy]} · seed {params.seed}
          </>
        }
      >
        {c.select('strategy', 'Strategy', STRATEGY_OPTIONS)}
        {c.number('seed', 'Seed')}
        <div className="al-row">
          <button type="button" onClick={() => set({ seed: (params.seed + 1) >>> 0 })}>
            New seed
          </button>
          <button type="button" aria-pressed={reseeding} onClick={onToggleReseeding}>
            {reseeding ? '❚❚ Stop reseeding' : '↻ Reseed every second'}
          </button>
        </div>
      </Fold>
      <Fold name="setup" className="al-fold" summary="Presets, the light and the floor">
        <h3 className="al-fold-heading">Presets</h3>
        <div className="al-presets" role="group" aria-label="Presets">
          {PRESETS.map((pr) => (
            <button
              key={pr.id}
              type="button"
              title={pr.what}
              aria-pressed={presetActive(pr, params)}
              onClick={() => set({ ...pr.params })}
              data-testid={`preset-${pr.id}`}
            >
              {pr.label}
            </button>
          ))}
        </div>
        <h3 className="al-fold-heading">Light and floor</h3>
        <VecField name="lc" label="Light centre" params={params} set={set} />
        {SIDES.map((label, k) => (
          <Slider
            key={label}
            label={label}
            value={size[k]}
            {...SIDE_RANGE}
            onChange={(x) => set({ ls: k === 0 ? [x, size[1]] : [size[0], x] })}
          />
        ))}
        {c.slider('tilt', 'Tilt about x', { min: -180, max: 180, step: 1, unit: '°' })}
        {c.slider('L', 'Radiance L', { max: 10, step: 0.1 })}
        {c.slider('rho', 'Albedo ρ', { step: 0.01 })}
        <VecField name="p" label="Shading point p (normal +z)" params={params} set={set} />
        {c.toggle('occluder', 'Occluder between point and light')}
      </Fold>
    </>
  );
});
