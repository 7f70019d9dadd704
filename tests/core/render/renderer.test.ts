/**
 * The CPU renderer: tiles rendered apart (as workers do) merge into exactly the whole image;
 * passes accumulate; the white furnace is 1 everywhere (exactly, by cosine sampling); on Veach's
 * scene, at equal total samples, MIS has a lower relMSE than either of its two techniques alone.
 */
import { describe, expect, it } from 'vitest';
import {
  makeCpuRenderer,
  newAccumulation,
  renderImage,
  renderTilePass,
  resolveImage,
} from '../../../src/core/render/cpuRenderer';
import { inspectPixel } from '../../../src/core/render/inspector';
import { relMse } from '../../../src/core/render/relMse';
import {
  EXAM_DEFAULTS,
  defaultView,
  examScene,
  furnaceScene,
  veachScene,
} from '../../../src/core/render/scene';
import { mergeTile, renderTileJob, splitRows } from '../../../src/core/render/tileJob';
import { STRATEGIES } from '../../../src/core/render/directLight';

describe('tiles and passes', () => {
  it('merges tiles rendered apart into exactly the image rendered whole', async () => {
    const W = 12,
      H = 10;
    const args = {
      spec: { scene: 'exam' as const, exam: EXAM_DEFAULTS },
      view: defaultView('exam'),
      width: W,
      height: H,
      seed: 9,
      strategy: 'mis-power' as const,
      bounces: 3,
      spp: 4,
      passSpp: 2,
    };
    const acc = newAccumulation(W, H);
    const tiles = splitRows(W, H, 3);
    expect(tiles.map((t) => t.h)).toEqual([3, 3, 4]);
    const fractions: number[] = [];
    for (const tile of tiles)
      mergeTile(acc, await renderTileJob({ ...args, tile }, (_r, f) => void fractions.push(f)));
    expect(fractions).toEqual([0.5, 1, 0.5, 1, 0.5, 1]);
    expect([...acc.count]).toEqual(new Array(W * H).fill(4));
    const direct = renderImage(makeCpuRenderer(examScene(), args.view, W, H, args, 9), W, H, 2, 2);
    expect(resolveImage(acc)).toEqual(direct);
    expect(direct.some((x) => x > 0)).toBe(true);
  });

  it('adds pass after pass to the sums and counts', () => {
    const r = makeCpuRenderer(
      furnaceScene(),
      defaultView('furnace'),
      4,
      4,
      { strategy: 'uniform', bounces: 1 },
      1,
    );
    const acc = newAccumulation(4, 4);
    const tile = { x0: 1, y0: 1, w: 2, h: 2 };
    expect(renderTilePass(r, acc, tile, 0, 3)).toBe(12);
    expect(renderTilePass(r, acc, tile, 1, 3)).toBe(12);
    expect(acc.count[5]).toBe(6);
    expect(acc.count[0]).toBe(0);
    expect(resolveImage(acc)[0]).toBe(0);
  });
});

describe('the white furnace', () => {
  it('renders exactly 1 everywhere by cosine sampling, at every bounce count', () => {
    for (const strategy of ['cosine', 'bsdf'] as const)
      for (const bounces of [1, 8]) {
        const r = makeCpuRenderer(furnaceScene(), defaultView('furnace'), 16, 16, { strategy, bounces }, 2);
        const img = renderImage(r, 16, 16, 1, 4);
        for (const x of img) expect(Math.abs(x - 1)).toBeLessThan(1e-12);
      }
  });

  it('every strategy’s estimate on the sphere is within 4σ of 1; cosine sampling is 1 to 1e-12', () => {
    const view = defaultView('furnace');
    for (const strategy of STRATEGIES)
      for (const bounces of [1, 4]) {
        const ins = inspectPixel(furnaceScene(), view, 16, 15, {
          width: 32,
          height: 32,
          seed: 4,
          strategy,
          bounces,
        });
        expect(ins.hit).toBe('sphere');
        expect(ins.referenceKind).toBe('exact');
        expect(ins.reference).toBe(1);
        if (strategy === 'cosine' || strategy === 'bsdf') {
          expect(Math.abs(ins.estimate - 1)).toBeLessThan(1e-12);
          expect(ins.stderr).toBeLessThan(1e-12);
        } else {
          expect(ins.stderr).toBeGreaterThan(0);
          expect(Math.abs(ins.estimate - 1)).toBeLessThan(4 * ins.stderr);
        }
      }
  });
});

describe('Veach’s scene', () => {
  it('at equal total samples, MIS’s relMSE is below both of its techniques’', () => {
    const W = 64,
      H = 48;
    const view = defaultView('veach');
    const scene = veachScene();
    const render = (strategy: (typeof STRATEGIES)[number], seed: number, passes: number) =>
      renderImage(makeCpuRenderer(scene, view, W, H, { strategy, bounces: 1 }, seed), W, H, passes, 16);
    const reference = render('mis-balance', 77, 8);
    const err = Object.fromEntries(
      (['bsdf', 'solid-angle', 'mis-balance', 'mis-power'] as const).map((s) => [
        s,
        relMse(render(s, 5, 1), reference),
      ]),
    );
    for (const mis of ['mis-balance', 'mis-power'])
      for (const single of ['bsdf', 'solid-angle']) expect(err[mis]).toBeLessThan(err[single]);
  });

  it('inspects a glossy plate against a converged reference, for both of MIS’s techniques', () => {
    const view = defaultView('veach');
    let found = 0;
    for (let j = 0; j < 48 && found < 2; j += 3) {
      const ins = inspectPixel(veachScene(), view, 40, j, {
        width: 64,
        height: 48,
        seed: 6,
        strategy: 'bsdf',
        bounces: 2,
        pn: 16,
      });
      if (ins.hit !== 'plate') continue;
      found++;
      expect(ins.albedo).toBeNull();
      expect(ins.u).toBeNull();
      for (const strategy of ['bsdf', 'solid-angle'] as const) {
        const r = inspectPixel(veachScene(), view, 40, j, {
          width: 64,
          height: 48,
          seed: 6,
          strategy,
          bounces: 2,
          pn: 2048,
        });
        expect(r.referenceKind).toBe('converged');
        expect(Math.abs(r.estimate - r.reference)).toBeLessThan(4 * Math.hypot(r.stderr, r.referenceStderr));
      }
    }
    expect(found).toBe(2);
  });
});
