/**
 * The line above the stage that says what the opening shows (a tilted light and a tilted patch,
 * so cos θ ≠ cos θₗ and dA⊥ ≠ dA) and switches, in one click, to the exam's configuration (the
 * light parallel to the floor, the patch flat on it) and back.
 */
import { memo } from 'react';
import { fmt } from './format';
import { isParallel, tiltFromFloor } from './describe';
import { EXAM_PRESET, OPENING_PRESET, presetActive, type AreaLightParams } from '../params';

export const ExamConfig = memo(function ExamConfig({
  params,
  tilt,
  patchCos,
  set,
}: {
  params: AreaLightParams;
  /** The light's tilt as used (degrees). */
  tilt: number;
  /** cos θₗ of the Q6(a) patch. */
  patchCos: number;
  set: (patch: Partial<AreaLightParams>) => void;
}) {
  const exam = presetActive(EXAM_PRESET, params);
  const parallel = isParallel(tilt);
  const patchAngle = (Math.acos(Math.min(1, Math.max(-1, patchCos))) * 180) / Math.PI;
  return (
    <div className="al-config" role="group" aria-label="Configuration" data-testid="al-config">
      <p className="al-note" data-testid="al-config-note">
        {parallel ? (
          <>
            Light parallel to the floor: cos θ = cos θ<sub>l</sub> at every sample.{' '}
          </>
        ) : (
          <>
            Light {fmt(tiltFromFloor(tilt), 2)}° from the floor: cos θ at the point ≠ cos θ<sub>l</sub> at the
            light.{' '}
          </>
        )}
        Patch {fmt(patchAngle, 2)}° from facing the point: dA⊥ = {fmt(patchCos, 3)} dA.
      </p>
      <div className="al-row">
        <button
          type="button"
          aria-pressed={exam}
          title={EXAM_PRESET.what}
          onClick={() => set({ ...EXAM_PRESET.params })}
          data-testid="exam-config"
        >
          {EXAM_PRESET.label}
        </button>
        <button
          type="button"
          aria-pressed={presetActive(OPENING_PRESET, params)}
          title={OPENING_PRESET.what}
          onClick={() => set({ ...OPENING_PRESET.params })}
          data-testid="opening-config"
        >
          {OPENING_PRESET.label}
        </button>
      </div>
    </div>
  );
});
