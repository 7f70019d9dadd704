/**
 * What the GPU renderer's shader reads, as plain arrays: the camera, the scene and the estimator's
 * options packed into the uniforms of ./glslScene and ./glslEstimator, and the texel grid as the
 * rows of an R32F texture (row 0 at v = 0, as core/texture/grid stores it). Pure, so a unit test
 * holds the packing against the scene it came from.
 */
import { makeCamera } from '../../../core/render/camera';
import { STRATEGIES } from '../../../core/render/directLight';
import { BIASES } from '../../../core/render/bias';
import { MAX_BOUNCES, MIN_BOUNCES, type TraceOptions } from '../../../core/render/pathTrace';
import type { RenderScene, View } from '../../../core/render/scene';
import type { RectLight } from '../../../core/lights/rectLight';

/** Most lights and most plates the shader holds (each preset has at most four). */
export const MAX_RECTS = 4;

/** A rectangle as four vec4: corner and ex, ey, n (unit) with w in the fourth slot of each. */
export interface PackedRects {
  count: number;
  corner: Float32Array;
  ex: Float32Array;
  ey: Float32Array;
  n: Float32Array;
}

export interface SceneUniforms {
  eye: Float32Array;
  fwd: Float32Array;
  right: Float32Array;
  up: Float32Array;
  /** tan(fov/2) · aspect and tan(fov/2). */
  scale: Float32Array;
  res: number;
  /** Floor albedo, −1 for no floor. */
  floor: number;
  /** Sphere centre and radius (radius 0: no sphere). */
  sphere: Float32Array;
  sphereAlbedo: number;
  /** 0: no texture, 1: bilinear, 2: nearest. */
  texFilter: 0 | 1 | 2;
  texRange: Float32Array;
  tex: { width: number; height: number; values: Float32Array };
  /** Lights: corner.w = L, ex.w = width, ey.w = height, n.w = area. */
  lights: PackedRects;
  /** Plates: corner.w = Phong exponent, ex.w = width, ey.w = height, n.w = ks. */
  plates: PackedRects;
  env: number;
  /** Index into STRATEGIES and BIASES, and the bounce count (1 … 8). */
  strategy: number;
  bias: number;
  bounces: number;
}

function packRects(rects: readonly { rect: RectLight; a: number; b: number }[]): PackedRects {
  const p: PackedRects = {
    count: Math.min(MAX_RECTS, rects.length),
    corner: new Float32Array(4 * MAX_RECTS),
    ex: new Float32Array(4 * MAX_RECTS),
    ey: new Float32Array(4 * MAX_RECTS),
    n: new Float32Array(4 * MAX_RECTS),
  };
  rects.slice(0, MAX_RECTS).forEach(({ rect, a, b }, k) => {
    p.corner.set([...rect.corner, a], 4 * k);
    p.ex.set([...rect.ex, rect.width], 4 * k);
    p.ey.set([...rect.ey, rect.height], 4 * k);
    p.n.set([...rect.normal, b], 4 * k);
  });
  return p;
}

/** The uniforms of a res × res render of the scene from the view with these options. */
export function sceneUniforms(
  scene: RenderScene,
  view: View,
  res: number,
  trace: TraceOptions,
): SceneUniforms {
  const cam = makeCamera(view, res, res);
  const s = scene.sphere;
  const grid = s?.texture ?? null;
  const bounces = Math.min(MAX_BOUNCES, Math.max(MIN_BOUNCES, Math.round(trace.bounces) || 1));
  return {
    eye: Float32Array.from(cam.eye),
    fwd: Float32Array.of(cam.fx, cam.fy, cam.fz),
    right: Float32Array.of(cam.rx, cam.ry, cam.rz),
    up: Float32Array.of(cam.ux, cam.uy, cam.uz),
    scale: Float32Array.of(cam.sx, cam.sy),
    res,
    floor: scene.floorAlbedo ?? -1,
    sphere: s ? Float32Array.of(...s.center, s.radius) : new Float32Array(4),
    sphereAlbedo: s?.albedo ?? 0,
    texFilter: grid ? (s?.filter === 'nearest' ? 2 : 1) : 0,
    texRange: Float32Array.of(s?.texMin ?? 0, s?.texMax ?? 1),
    tex: grid
      ? { width: grid.width, height: grid.height, values: Float32Array.from(grid.values) }
      : { width: 1, height: 1, values: new Float32Array(1) },
    lights: packRects(scene.lights.map((l) => ({ rect: l.rect, a: l.L, b: l.rect.area }))),
    plates: packRects(scene.plates.map((p) => ({ rect: p.rect, a: p.exponent, b: p.ks }))),
    env: scene.environment,
    strategy: STRATEGIES.indexOf(trace.strategy),
    bias: BIASES.indexOf(trace.bias ?? 'none'),
    bounces,
  };
}
