/**
 * The GPU renderer's inputs, held against the scene they come from: the camera frame, the floor,
 * the sphere and its texel grid, every light and plate packed into its four vec4 (with L, width,
 * height, area or the Phong exponent and ks in the fourth slots), the environment and the
 * estimator's options as the shader's indices.
 */
import { describe, expect, it } from 'vitest';
import { sceneUniforms, MAX_RECTS } from '../../../../src/scenes/render/gpu/sceneUniforms';
import { makeCamera } from '../../../../src/core/render/camera';
import {
  buildScene,
  defaultView,
  EXAM_DEFAULTS,
  examScene,
  furnaceScene,
  veachScene,
} from '../../../../src/core/render/scene';
import { STRATEGIES } from '../../../../src/core/render/directLight';

const f32 = (xs: readonly number[]) => Array.from(Float32Array.from(xs));

describe('sceneUniforms', () => {
  it('packs the exam scene: camera, floor, textured sphere, one light', () => {
    const scene = examScene({ ...EXAM_DEFAULTS, filter: 'nearest' });
    const view = defaultView('exam');
    const u = sceneUniforms(scene, view, 48, { strategy: 'mis-power', bounces: 3, bias: 'clamp' });
    const cam = makeCamera(view, 48, 48);
    expect(Array.from(u.eye)).toEqual(f32(view.eye));
    expect(Array.from(u.fwd)).toEqual(f32([cam.fx, cam.fy, cam.fz]));
    expect(Array.from(u.right)).toEqual(f32([cam.rx, cam.ry, cam.rz]));
    expect(Array.from(u.up)).toEqual(f32([cam.ux, cam.uy, cam.uz]));
    expect(Array.from(u.scale)).toEqual(f32([cam.sx, cam.sy]));
    expect(u.res).toBe(48);
    expect(u.floor).toBe(0.8);
    expect(Array.from(u.sphere)).toEqual([0, 0, 0, 1]);
    expect(u.texFilter).toBe(2);
    const s = scene.sphere!;
    expect(Array.from(u.texRange)).toEqual(f32([s.texMin, s.texMax]));
    expect(u.tex.width).toBe(5);
    expect(u.tex.height).toBe(5);
    // row 0 of the texture is the grid's row 0 (v = 0): the exam's value(i, j) = 21 − 5j + i
    expect(Array.from(u.tex.values)).toEqual(f32(Array.from(s.texture!.values)));
    expect(u.tex.values[1 * 5 + 2]).toBe(s.texture!.values[7]);
    const l = scene.lights[0];
    expect(u.lights.count).toBe(1);
    expect(Array.from(u.lights.corner.slice(0, 4))).toEqual(f32([...l.rect.corner, l.L]));
    expect(Array.from(u.lights.ex.slice(0, 4))).toEqual(f32([...l.rect.ex, l.rect.width]));
    expect(Array.from(u.lights.ey.slice(0, 4))).toEqual(f32([...l.rect.ey, l.rect.height]));
    expect(Array.from(u.lights.n.slice(0, 4))).toEqual(f32([...l.rect.normal, l.rect.area]));
    expect(Array.from(u.lights.corner.slice(4))).toEqual(new Array(4 * (MAX_RECTS - 1)).fill(0));
    expect(u.plates.count).toBe(0);
    expect(u.env).toBe(0);
    expect(u.strategy).toBe(STRATEGIES.indexOf('mis-power'));
    expect(u.bias).toBe(2);
    expect(u.bounces).toBe(3);
  });

  it('packs the furnace: no floor, an untextured sphere of albedo 1, the environment', () => {
    const u = sceneUniforms(furnaceScene(), defaultView('furnace'), 32, { strategy: 'cosine', bounces: 12 });
    expect(u.floor).toBe(-1);
    expect(u.texFilter).toBe(0);
    expect(u.sphereAlbedo).toBe(1);
    expect(u.env).toBe(1);
    expect(u.lights.count).toBe(0);
    expect(u.strategy).toBe(1);
    expect(u.bias).toBe(0);
    expect(u.bounces).toBe(8);
  });

  it('packs Veach’s four lights (equal power) and four plates (exponent, ks)', () => {
    const scene = veachScene();
    const u = sceneUniforms(scene, defaultView('veach'), 32, { strategy: 'area', bounces: 1 });
    expect(u.sphere[3]).toBe(0);
    expect(u.lights.count).toBe(4);
    expect(u.plates.count).toBe(4);
    scene.lights.forEach((l, k) => {
      expect(u.lights.corner[4 * k + 3]).toBe(Math.fround(l.L));
      expect(u.lights.corner[4 * k + 3] * u.lights.n[4 * k + 3]).toBeCloseTo(0.3, 6);
    });
    scene.plates.forEach((p, k) => {
      expect(Array.from(u.plates.corner.slice(4 * k, 4 * k + 4))).toEqual(
        f32([...p.rect.corner, p.exponent]),
      );
      expect(u.plates.n[4 * k + 3]).toBe(Math.fround(p.ks));
      expect(Array.from(u.plates.n.slice(4 * k, 4 * k + 3))).toEqual(f32([...p.rect.normal]));
    });
    expect(buildScene({ scene: 'veach', exam: EXAM_DEFAULTS }).lights).toHaveLength(4);
  });
});
