/**
 * The CPU renderer's image with its per-pixel noise: `spp` samples per pixel, drawn exactly as the
 * progressive render draws them (pass p of one sample: Rng(runSeed(seed, p), pixel), sample index
 * p), summed with their squares, so each pixel has a mean and a standard error. What the comparison
 * of the two renderers (./rendererCompare) takes from the float64 side.
 */
import { Rng, runSeed } from '../random/rng';
import { cameraRay } from './camera';
import type { CpuRenderer } from './cpuRenderer';
import { radiance } from './pathTrace';
import { momentsFromSums } from './rendererCompare';

export function renderMoments(
  r: CpuRenderer,
  width: number,
  height: number,
  spp: number,
): { mean: Float64Array; se2: Float64Array } {
  const { cam, tracer, dir } = r;
  const e = cam.eye;
  const sum = new Float64Array(width * height);
  const sumSq = new Float64Array(width * height);
  for (let p = 0; p < spp; p++) {
    const passSeed = runSeed(r.seed, p);
    for (let k = 0; k < width * height; k++) {
      const i = k % width,
        j = (k - i) / width;
      const rng = new Rng(passSeed, k);
      cameraRay(cam, i, j, rng.nextFloat(), rng.nextFloat(), dir);
      const x = radiance(tracer, e[0], e[1], e[2], dir[0], dir[1], dir[2], p, rng);
      sum[k] += x;
      sumSq[k] += x * x;
    }
  }
  return momentsFromSums(sum, sumSq, spp);
}
