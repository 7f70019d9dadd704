/**
 * Q5's controls beside the figure: the presets (the five cases, and the inputs that break the
 * textbook form) and the typed values of the ray and the sphere.
 */
import { memo } from 'react';
import { NumberField } from '../../../ui';
import { bindControls } from '../../../ui/paramControls';
import { VectorField } from '../../../ui/VectorField';
import { PRECISION_OPTIONS } from '../view/Float32Panel';
import type { Vec3 } from '../../../core/vec3';
import { CASE_PRESETS, PRECISION_PRESETS, schema, type Preset, type RaySphereParams } from '../params';

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

function PresetGroup({
  name,
  heading,
  presets,
  active,
  setParams,
}: {
  /** The group's accessible name, and the words before its buttons. */
  name: string;
  heading: string;
  presets: readonly Preset[];
  active: Preset | undefined;
  setParams: SetParams;
}) {
  return (
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
  );
}

/** Both preset groups and what the active preset shows (memoised: `active` has a stable identity). */
export const Q5Presets = memo(function Q5Presets({
  active,
  setParams,
}: {
  active: Preset | undefined;
  setParams: SetParams;
}) {
  return (
    <div className="rs-preset-groups">
      <PresetGroup
        name="Case presets"
        heading="Cases:"
        presets={CASE_PRESETS}
        active={active}
        setParams={setParams}
      />
      <PresetGroup
        name="Precision presets"
        heading="Break the textbook form:"
        presets={PRECISION_PRESETS}
        active={active}
        setParams={setParams}
      />
      {active ? <p className="rs-small rs-preset-what">{active.what}</p> : null}
    </div>
  );
});

const BIG = 1e12;

/** The three vectors of the ray and the sphere, typed as x, y, z (test ids `input-<name>-<axis>`). */
const VECTORS = [
  { name: 'o', label: 'Origin o' },
  { name: 'd', label: 'Direction d' },
  { name: 'c', label: 'Centre C (URL parameter c)' },
] as const;

interface VecFieldProps {
  name: (typeof VECTORS)[number]['name'];
  label: string;
  value: Vec3;
  edit: SetParams;
}

function VecField({ name, label, value, edit }: VecFieldProps) {
  return (
    <VectorField
      label={label}
      value={value}
      min={-BIG}
      max={BIG}
      testIdPrefix={`input-${name}`}
      onChange={(v) => edit({ [name]: v })}
    />
  );
}

/** The readouts' method and arithmetic, as selects bound to their URL parameters. */
const READOUT_SCHEMA = { method: schema.method, precision: schema.precision };
const METHOD_OPTIONS = [
  { value: 'stable', label: 'robust (Ray Tracing Gems ch. 7)' },
  { value: 'naive', label: 'textbook (−b\u00a0±\u00a0√Δ) / 2a' },
] as const;

export interface Q5FieldsProps extends Pick<RaySphereParams, 'o' | 'd' | 'c' | 'r' | 'method' | 'precision'> {
  setParams: SetParams;
  /** An edit of the ray or sphere: it moves the sweep's centre to the ray on screen. */
  edit: SetParams;
}

/** The typed values (memoised: a re-render of the scene with the same values leaves it alone). */
export const Q5Fields = memo(function Q5Fields({
  o,
  d,
  c,
  r,
  method,
  precision,
  setParams,
  edit,
}: Q5FieldsProps) {
  const bound = bindControls<typeof READOUT_SCHEMA>(READOUT_SCHEMA, { method, precision }, setParams);
  const vectors = { o, d, c };
  return (
    <details className="rs-fields" open={typeof window === 'undefined' || window.innerWidth > 820}>
      <summary>Ray o + t d and sphere (centre C, radius r): type values</summary>
      {bound.select('method', 'Method (for the readouts)', METHOD_OPTIONS)}
      {bound.select('precision', 'Arithmetic (for the readouts)', PRECISION_OPTIONS)}
      {VECTORS.map(({ name, label }) => (
        <VecField key={name} name={name} label={label} value={vectors[name]} edit={edit} />
      ))}
      <NumberField
        label="Radius r"
        value={r}
        onChange={(x) => edit({ r: x })}
        min={-BIG}
        max={BIG}
        step={0.1}
        testId="input-r"
      />
      <p className="rs-small">
        d need not be unit length: t is then measured in units of |d|. These fields hold the ray at the centre
        of the sweep (sweep position τ = 0.5); editing moves the sweep there.
      </p>
    </details>
  );
});
