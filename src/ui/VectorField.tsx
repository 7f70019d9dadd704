import type { Vec3 } from '../core/vec3';
import { NumberField } from './controls';
import './controls.css';

const AXES = ['x', 'y', 'z'] as const;

/**
 * A 3-vector typed as three number fields (x, y, z) in one labelled group. Editing one component
 * hands the whole new vector to `onChange`; each field keeps the value within [min, max] as a
 * NumberField does. Test ids are `<testIdPrefix>-x`, `-y`, `-z`.
 */
export function VectorField({
  label,
  value,
  min,
  max,
  step = 0.1,
  testIdPrefix,
  onChange,
}: {
  label: string;
  value: Vec3;
  min: number;
  max: number;
  step?: number;
  testIdPrefix: string;
  onChange: (next: [number, number, number]) => void;
}) {
  return (
    <fieldset className="vec-field">
      <legend>{label}</legend>
      {AXES.map((axis, k) => (
        <NumberField
          key={axis}
          label={axis}
          value={value[k]}
          step={step}
          min={min}
          max={max}
          testId={`${testIdPrefix}-${axis}`}
          onChange={(x) => {
            const next: [number, number, number] = [value[0], value[1], value[2]];
            next[k] = x;
            onChange(next);
          }}
        />
      ))}
    </fieldset>
  );
}
