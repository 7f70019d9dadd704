/**
 * The emitters of a scene as one light to sample: the rectangle lights and, where the scene has
 * one, the uniform environment. A light sample picks one of the K emitters uniformly (pbrt-v4's
 * `UniformLightSampler`, §12.6) and then a point on it:
 *
 * - by AREA (exam Q6(c); core/lights/areaSampling): density 1/(K |A|) per unit area, converted to
 *   solid angle at the shading point by r²/|cos θ_l| (exam Q6(a));
 * - by SOLID ANGLE (Arvo 1995, Ureña et al. 2013; core/lights/sphericalRectangle): density
 *   1/(K Ω) per steradian;
 * - the environment by a uniform direction on the sphere, 1/(4π K) per steradian (pbrt-v4
 *   `UniformInfiniteLight::SampleLi`).
 *
 * {@link lightPdf} is the density the solid-angle light technique has at a given point or
 * direction; multiple importance sampling weighs a BSDF sample with it.
 */
import {
  makeSphericalRect,
  sampleSphericalRectangle,
  sphericalRectanglePdf,
  type SphericalRect,
} from '../lights/sphericalRectangle';
import { sampleRectArea } from '../lights/areaSampling';
import type { RenderScene } from './scene';

const INV_FOUR_PI = 1 / (4 * Math.PI);

/** How the light technique places its point: uniformly by area, or uniformly by solid angle. */
export type LightMeasure = 'area' | 'solid-angle';

/** The number of emitters K: the rectangle lights, plus one for a non-black environment. */
export function emitterCount(scene: RenderScene): number {
  return scene.lights.length + (scene.environment > 0 ? 1 : 0);
}

/** The solid-angle samplers of every light from one shading point (rebuilt per point). */
export interface LightFrames {
  rects: SphericalRect[];
}

/** Set up solid-angle sampling of every light from the point p. */
export function lightFramesAt(scene: RenderScene, px: number, py: number, pz: number): LightFrames {
  return { rects: scene.lights.map((l) => makeSphericalRect(l.rect, px, py, pz)) };
}

/** A sample of the emitters: which one, the point (or, for the environment, the direction). */
export interface EmitterSample {
  /** Index of the light, or −1 for the environment. */
  light: number;
  /** The point on the light; for the environment, the unit direction. */
  x: number;
  y: number;
  z: number;
  /** Density in the technique's own measure: per unit area (area) or per steradian. */
  pdf: number;
}

/**
 * Pick an emitter with u0 ∈ [0, 1) and sample it with (u1, u2) by `measure`; fills `out`.
 * Returns false when the scene has no emitter.
 */
export function sampleEmitter(
  scene: RenderScene,
  frames: LightFrames | null,
  measure: LightMeasure,
  u0: number,
  u1: number,
  u2: number,
  out: EmitterSample,
  buf: Float64Array,
): boolean {
  const K = emitterCount(scene);
  if (K === 0) return false;
  const k = Math.min(K - 1, Math.floor(u0 * K));
  if (k === scene.lights.length) {
    const z = 1 - 2 * u1;
    const r = Math.sqrt(Math.max(0, (1 - z) * (1 + z)));
    const phi = 2 * Math.PI * u2;
    out.light = -1;
    out.x = r * Math.cos(phi);
    out.y = r * Math.sin(phi);
    out.z = z;
    out.pdf = INV_FOUR_PI / K;
    return true;
  }
  const light = scene.lights[k];
  out.light = k;
  if (measure === 'area' || !frames) {
    sampleRectArea(light.rect, u1, u2, buf);
    out.pdf = light.rect.area > 0 ? 1 / (K * light.rect.area) : 0;
  } else {
    const q = frames.rects[k];
    sampleSphericalRectangle(q, u1, u2, buf);
    out.pdf = sphericalRectanglePdf(q, buf[0], buf[1], buf[2]) / K;
  }
  out.x = buf[0];
  out.y = buf[1];
  out.z = buf[2];
  return true;
}

/**
 * The density per steradian with which the solid-angle light technique picks the point x on light
 * k (k = −1: the environment, in any direction) as seen from the frames' point.
 */
export function lightPdf(
  scene: RenderScene,
  frames: LightFrames,
  k: number,
  x: number,
  y: number,
  z: number,
): number {
  const K = emitterCount(scene);
  if (K === 0) return 0;
  if (k < 0) return scene.environment > 0 ? INV_FOUR_PI / K : 0;
  return sphericalRectanglePdf(frames.rects[k], x, y, z) / K;
}
