/**
 * The CPU renderer's image with its per-pixel noise: `spp` passes of one sample per pixel, drawn
 * exactly as the progressive render draws them (./cpuRenderer renderTilePass), summed with their
 * squares, so each pixel has a mean and a standard error. What the comparison of the two renderers
 * (./rendererCompare) takes from the float64 side.
 */
import { newAccumulation, renderTilePass, type CpuRenderer } from './cpuRenderer';
import { momentsFromSums } from './rendererCompare';

export function renderMoments(
  r: CpuRenderer,
  width: number,
  height: number,
  spp: number,
): { mean: Float64Array; se2: Float64Array } {
  const acc = newAccumulation(width, height);
  const sumSq = new Float64Array(width * height);
  const whole = { x0: 0, y0: 0, w: width, h: height };
  for (let p = 0; p < spp; p++) renderTilePass(r, acc, whole, p, 1, sumSq);
  return momentsFromSums(acc.sum, sumSq, spp);
}
