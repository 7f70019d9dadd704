/** A column of sliders described by data: each reads its value from, and writes a patch to, the parameters. */
import { Slider } from '../../../ui';
import type { AreaLightParams } from '../params';

/** One slider: its label and range, and how it reads `values` and patches the parameters. */
export interface SliderSpec<V> {
  label: string;
  min: number;
  max: number;
  step?: number;
  log?: boolean;
  unit?: string;
  get: (values: V) => number;
  patch: (x: number, values: V) => Partial<AreaLightParams>;
}

export function SliderList<V>({
  specs,
  values,
  set,
}: {
  specs: readonly SliderSpec<V>[];
  values: V;
  set: (patch: Partial<AreaLightParams>) => void;
}) {
  return (
    <>
      {specs.map(({ get, patch, ...range }) => (
        <Slider key={range.label} {...range} value={get(values)} onChange={(x) => set(patch(x, values))} />
      ))}
    </>
  );
}
