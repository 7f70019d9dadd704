/**
 * The float32 / GPU section of the hemisphere scene, as the scene mounts it: a disclosure whose
 * content (the float32 table, the WebGL2 vertex-shader pass, its χ² test) is a lazy chunk.
 */
import { lazy } from 'react';
import { Fold } from '../../../ui/Fold';

const GpuWarpPanel = lazy(() => import('./GpuWarpPanel').then((m) => ({ default: m.GpuWarpPanel })));

export function GpuWarpSection({ seed }: { seed: number }) {
  return (
    <Fold
      name="gpu-warp"
      testId="gpu-warp-details"
      summary="The exam’s warps in float32, and 10⁶ directions sampled and drawn by a WebGL2 vertex shader (χ²-tested)"
    >
      <GpuWarpPanel seed={seed} />
    </Fold>
  );
}
