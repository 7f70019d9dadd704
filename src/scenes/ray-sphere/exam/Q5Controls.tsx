/**
 * Q5's controls. On the page only the readouts' method stays in view (with the case presets beside
 * the figure, ./Q5Presets); typing the ray and the sphere, and the settings beyond the exam (the
 * sweep, float32 arithmetic, the inputs that break the textbook form), are folds. On the classroom
 * stage (`present=1`) all of them sit in the drawer, unfolded.
 */
import { memo } from 'react';
import { Fold } from '../../../ui/Fold';
import { NumberField } from '../../../ui';
import { bindControls } from '../../../ui/paramControls';
import { VectorField } from '../../../ui/VectorField';
import { PRECISION_OPTIONS } from '../view/Float32Panel';
import type { Vec3 } from '../../../core/vec3';
import type { Sweep } from '../sweep';
import { schema, type Preset, type RaySphereParams } from '../params';
import { CasePresets, PrecisionPresets } from './Q5Presets';

type SetParams = (patch: Partial<RaySphereParams>) => void;

const SWEEP_SCHEMA = { sweep: schema.sweep };
const SWEEP_OPTIONS = [
  { value: 'offset', label: 'origin moves across the ray' },
  { value: 'rotate', label: 'direction turns about o' },
] as const;

/** The sweep's mode and extent. */
function SweepControls({ sweep, extent, setParams }: { sweep: Sweep; extent: number; setParams: SetParams }) {
  const bound = bindControls<typeof SWEEP_SCHEMA>(SWEEP_SCHEMA, { sweep: sweep.mode }, setParams);
  return (
    <div className="rs-sweep-controls">
      {bound.select('sweep', 'Sweep', SWEEP_OPTIONS, { testId: 'sweep-mode' })}
      <NumberField
        label={sweep.mode === 'offset' ? 'extent (± radii)' : 'extent (± angular radii)'}
        value={extent}
        onChange={(x) => setParams({ extent: x })}
        min={0.05}
        max={1000}
        step={0.5}
        testId="sweep-extent"
      />
    </div>
  );
}

/** The readouts' method and arithmetic, as selects bound to their URL parameters. */
const METHOD_SCHEMA = { method: schema.method };
const METHOD_OPTIONS = [
  { value: 'stable', label: 'robust (Ray Tracing Gems ch. 7)' },
  { value: 'naive', label: 'textbook (−b\u00a0±\u00a0√Δ) / 2a' },
] as const;
const PRECISION_SCHEMA = { precision: schema.precision };

function MethodSelect({ method, setParams }: { method: RaySphereParams['method']; setParams: SetParams }) {
  const bound = bindControls<typeof METHOD_SCHEMA>(METHOD_SCHEMA, { method }, setParams);
  return bound.select('method', 'Method (for the readouts)', METHOD_OPTIONS);
}

function ArithmeticSelect({
  precision,
  setParams,
}: {
  precision: RaySphereParams['precision'];
  setParams: SetParams;
}) {
  const bound = bindControls<typeof PRECISION_SCHEMA>(PRECISION_SCHEMA, { precision }, setParams);
  return bound.select('precision', 'Arithmetic (for the readouts)', PRECISION_OPTIONS);
}

const BIG = 1e12;

/** The three vectors of the ray and the sphere, typed as x, y, z (test ids `input-<name>-<axis>`). */
const VECTORS = [
  { name: 'o', label: 'Origin o' },
  { name: 'd', label: 'Direction d' },
  { name: 'c', label: 'Centre C (URL parameter c)' },
] as const;

interface FieldsProps extends Pick<RaySphereParams, 'o' | 'd' | 'c' | 'r'> {
  /** An edit of the ray or sphere: it moves the sweep's centre to the ray on screen. */
  edit: SetParams;
}

/** The typed values (memoised: a re-render of the scene with the same values leaves it alone). */
const Q5Fields = memo(function Q5Fields({ o, d, c, r, edit }: FieldsProps) {
  const vectors = { o, d, c };
  return (
    <div className="rs-fields">
      {VECTORS.map(({ name, label }) => (
        <VectorField
          key={name}
          label={label}
          value={vectors[name] as Vec3}
          min={-BIG}
          max={BIG}
          testIdPrefix={`input-${name}`}
          onChange={(v) => edit({ [name]: v })}
        />
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
    </div>
  );
});

export interface Q5ControlsProps extends FieldsProps, Pick<RaySphereParams, 'method' | 'precision'> {
  sweep: Sweep;
  extent: number;
  /** The preset whose values are the URL's, if any. */
  active: Preset | undefined;
  setParams: SetParams;
  /** In the classroom stage's drawer: everything, unfolded. */
  staged: boolean;
}

export function Q5Controls(props: Q5ControlsProps) {
  const { o, d, c, r, edit, method, precision, sweep, extent, active, setParams, staged } = props;
  const fields = <Q5Fields o={o} d={d} c={c} r={r} edit={edit} />;
  const sweepControls = <SweepControls sweep={sweep} extent={extent} setParams={setParams} />;
  const arithmetic = <ArithmeticSelect precision={precision} setParams={setParams} />;
  const breakers = <PrecisionPresets active={active} setParams={setParams} />;
  if (staged)
    return (
      <>
        {sweepControls}
        <CasePresets active={active} setParams={setParams} />
        {breakers}
        <MethodSelect method={method} setParams={setParams} />
        {arithmetic}
        {fields}
      </>
    );
  return (
    <>
      <MethodSelect method={method} setParams={setParams} />
      <Fold name="values" summary="Type the ray and the sphere: o, d, C and r">
        {fields}
      </Fold>
      <Fold name="more" summary="More settings: the sweep, float32, hard cases">
        {sweepControls}
        {arithmetic}
        {breakers}
      </Fold>
    </>
  );
}
