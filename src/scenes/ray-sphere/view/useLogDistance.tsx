/**
 * The distance of a far sphere, chosen on a log scale: the state e = log₁₀(D / r) (from 10^0.5, in
 * quarter steps, up to 10^max), the distance D = 10^e, and the slider that sets it. The
 * distant-sphere images and the GPU panel each keep one.
 */
import { useState } from 'react';
import { Slider } from '../../../ui';

export function useLogDistance(initial: number, slider: { label: string; max: number; testId: string }) {
  const [exp, setExp] = useState(initial);
  const { label, max, testId } = slider;
  return {
    exp,
    setExp,
    dist: 10 ** exp,
    slider: (
      <Slider label={label} value={exp} min={0.5} max={max} step={0.25} onChange={setExp} testId={testId} />
    ),
  };
}
