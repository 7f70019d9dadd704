/**
 * The control column of #/area-light: presets, the sampling strategy with n and the seed, and the
 * light, floor and shading point.
 */
import { memo } from 'react';
import type { Vec3 } from '../../../core/lights';
import { NumberField, Panel, Select, Slider, Toggle } from '../../../ui';
import { SliderList, type SliderSpec } from './SliderList';
import { PRESETS, presetActive, type AreaLightParams } from '../params';
import { STRATEGIES, STRATEGY_LABEL } from '../strategies';

const AXES = ['x', 'y', 'z'] as const;

/** The light's size, tilt and radiance and the floor's albedo. */
const LIGHT_SLIDERS: readonly SliderSpec<AreaLightParams>[] = [
  {
    label: 'Width w',
    min: 0,
    max: 10,
    step: 0.05,
    get: (p) => p.ls?.[0] ?? 1,
    patch: (x, p) => ({ ls: [x, p.ls?.[1] ?? 1] }),
  },
  {
    label: 'Height h',
    min: 0,
    max: 10,
    step: 0.05,
    get: (p) => p.ls?.[1] ?? 1,
    patch: (x, p) => ({ ls: [p.ls?.[0] ?? 1, x] }),
  },
  {
    label: 'Tilt about x',
    min: -180,
    max: 180,
    step: 1,
    unit: '°',
    get: (p) => p.tilt,
    patch: (tilt) => ({ tilt }),
  },
  { label: 'Radiance L', min: 0, max: 10, step: 0.1, get: (p) => p.L, patch: (L) => ({ L }) },
  { label: 'Albedo ρ', min: 0, max: 1, step: 0.01, get: (p) => p.rho, patch: (rho) => ({ rho }) },
];

/** Three number fields for a vector parameter (test ids `<testId>-x`, `-y`, `-z`). */
function VecField({
  label,
  testId,
  value,
  onChange,
}: {
  label: string;
  testId: string;
  value: readonly number[];
  onChange: (v: Vec3) => void;
}) {
  return (
    <fieldset className="al-vec">
      <legend>{label}</legend>
      {AXES.map((axis, k) => (
        <NumberField
          key={axis}
          label={axis}
          value={value[k]}
          step={0.1}
          min={-1e9}
          max={1e9}
          testId={`${testId}-${axis}`}
          onChange={(x) => {
            const next: Vec3 = [value[0], value[1], value[2]];
            next[k] = x;
            onChange(next);
          }}
        />
      ))}
    </fieldset>
  );
}

export const Controls = memo(function Controls({
  params,
  set,
  reseeding,
  onToggleReseeding,
}: {
  params: AreaLightParams;
  set: (patch: Partial<AreaLightParams>) => void;
  reseeding: boolean;
  onToggleReseeding: () => void;
}) {
  return (
    <>
      <Panel title="Presets">
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
      </Panel>
      <Panel title="Sampling">
        <Select
          label="Strategy"
          value={params.strategy}
          options={STRATEGIES.map((s) => ({ value: s, label: STRATEGY_LABEL[s] }))}
          onChange={(s) => set({ strategy: s })}
          testId="strategy"
        />
        <Slider
          label="Samples n"
          value={params.n}
          min={1}
          max={1000000}
          step={1}
          log
          onChange={(x) => set({ n: Math.round(x) })}
        />
        <NumberField
          label="Seed"
          value={params.seed}
          min={0}
          max={4294967295}
          step={1}
          onChange={(x) => set({ seed: Math.round(x) })}
        />
        <div className="al-row">
          <button type="button" onClick={() => set({ seed: (params.seed + 1) >>> 0 })}>
            New seed
          </button>
          <button type="button" aria-pressed={reseeding} onClick={onToggleReseeding}>
            {reseeding ? '❚❚ Stop reseeding' : '↻ Reseed every second'}
          </button>
        </div>
      </Panel>
      <Panel title="Light and floor">
        <VecField label="Light centre" testId="lc" value={params.lc} onChange={(v) => set({ lc: v })} />
        <SliderList specs={LIGHT_SLIDERS} values={params} set={set} />
        <VecField
          label="Shading point p (normal +z)"
          testId="p"
          value={params.p}
          onChange={(v) => set({ p: v })}
        />
        <Toggle
          label="Occluder between point and light"
          checked={params.occluder}
          onChange={(b) => set({ occluder: b })}
        />
      </Panel>
    </>
  );
});
