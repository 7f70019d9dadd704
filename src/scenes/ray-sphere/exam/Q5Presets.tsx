/**
 * Q5's preset buttons: the five cases the exam's answer distinguishes (beside the figure), and the
 * inputs that break the textbook form (under "More settings"). A preset sets the ray and the
 * sphere and moves the sweep to its centre; the active one is pressed and says what it shows.
 */
import { memo } from 'react';
import { CASE_PRESETS, PRECISION_PRESETS, type Preset, type RaySphereParams } from '../params';

type SetParams = (patch: Partial<RaySphereParams>) => void;

/** The preset whose values are those of the URL, if any (one of the module-level preset objects). */
export function activePresetOf(params: RaySphereParams): Preset | undefined {
  return [...CASE_PRESETS, ...PRECISION_PRESETS].find((p) => samePreset(p, params));
}

function samePreset(p: Preset, params: RaySphereParams): boolean {
  const eq = (x: readonly number[] | undefined, y: readonly number[]) => !x || x.every((v, i) => v === y[i]);
  return (
    eq(p.params.o, params.o) &&
    eq(p.params.d, params.d) &&
    eq(p.params.c, params.c) &&
    (p.params.r === undefined || p.params.r === params.r)
  );
}

interface PresetGroupProps {
  /** The preset whose values are the URL's (a module-level object: a stable identity). */
  active: Preset | undefined;
  setParams: SetParams;
}

/** One row of preset buttons, and what the active preset shows when it is one of them. */
function PresetGroup({
  name,
  heading,
  presets,
  active,
  setParams,
}: PresetGroupProps & {
  /** The group's accessible name, and the words before its buttons. */
  name: string;
  heading: string;
  presets: readonly Preset[];
}) {
  const mine = active && presets.includes(active) ? active : undefined;
  return (
    <div className="rs-preset-group">
      <div className="rs-presets" role="group" aria-label={name}>
        <span className="rs-presets-label">{heading}</span>
        {presets.map((p) => (
          <button
            key={p.id}
            type="button"
            data-testid={`preset-${p.id}`}
            aria-pressed={active?.id === p.id}
            onClick={() => setParams({ ...p.params, t: 0.5, play: false })}
          >
            {p.label}
          </button>
        ))}
      </div>
      {mine ? <p className="rs-small rs-preset-what">{mine.what}</p> : null}
    </div>
  );
}

/** The five cases: two hits, miss, tangent, origin inside, sphere behind. */
export const CasePresets = memo(function CasePresets(props: PresetGroupProps) {
  return <PresetGroup name="Case presets" heading="Cases:" presets={CASE_PRESETS} {...props} />;
});

/** The far sphere, the grazing ray and the rays one ulp either side of tangent. */
export const PrecisionPresets = memo(function PrecisionPresets(props: PresetGroupProps) {
  return (
    <PresetGroup
      name="Precision presets"
      heading="Break the textbook form:"
      presets={PRECISION_PRESETS}
      {...props}
    />
  );
});
