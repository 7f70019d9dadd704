/**
 * The render lab's CPU renderer (core/render/cpuRenderer), what one worker does: one pass of one
 * sample per pixel over a 64 × 64 tile, for the exam scene with mis-power at one bounce and the
 * white furnace at three bounces. The page runs one such tile job per worker, so paths per second
 * here are paths per second per worker. Run with `npx vitest bench bench/render.bench.ts --run`.
 */
import { bench, describe } from 'vitest';
import { makeCpuRenderer, newAccumulation, renderTilePass } from '../src/core/render/cpuRenderer';
import { defaultView, examScene, furnaceScene } from '../src/core/render/scene';

const RES = 64;
const tile = { x0: 0, y0: 0, w: RES, h: RES };

function tilePass(
  scene: ReturnType<typeof examScene>,
  view: ReturnType<typeof defaultView>,
  bounces: number,
) {
  const r = makeCpuRenderer(scene, view, RES, RES, { strategy: 'mis-power', bounces }, 1);
  const acc = newAccumulation(RES, RES);
  let pass = 0;
  return () => {
    renderTilePass(r, acc, tile, pass++, 1);
  };
}

describe(`render lab CPU tile pass, ${RES * RES} samples per iteration (paths per worker)`, () => {
  bench('exam scene, mis-power, 1 bounce', tilePass(examScene(), defaultView('exam'), 1));
  bench('white furnace, mis-power, 3 bounces', tilePass(furnaceScene(), defaultView('furnace'), 3));
});
