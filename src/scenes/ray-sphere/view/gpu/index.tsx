/**
 * The GPU section of the ray–sphere scene, as the scene mounts it: a disclosure whose content
 * (the WebGL2 shader, the float32 images, self-intersection in float32) is a lazy chunk.
 */
import { lazy } from 'react';
import { Fold } from '../../../../ui/Fold';

const GpuSpherePanel = lazy(() => import('./GpuSpherePanel').then((m) => ({ default: m.GpuSpherePanel })));

export function GpuSection() {
  return (
    <Fold
      name="gpu"
      testId="gpu-details"
      summary="What the GPU sees: the textbook and robust tests in a WebGL2 shader (float32), beside the emulation and float64"
    >
      <GpuSpherePanel />
    </Fold>
  );
}
