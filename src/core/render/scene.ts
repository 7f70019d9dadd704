/**
 * The render lab's scenes as plain data: what is where and what it is made of. Three presets:
 *
 * - `exam`: the exam's objects in one picture. The floor z = 0 (Lambertian, albedo ρ) under the
 *   rectangular light of the area-light question (centre lc, size ls, tilt, radiance L; its frame
 *   is core/lights/rectLight), and the sphere of the ray–sphere question (centre c, radius r),
 *   textured with the texture question's grid by the exam's spherical (u, v) mapping (about the
 *   sphere's centre) and a bilinear or nearest lookup. The texel value becomes the sphere's
 *   albedo by {@link texelAlbedo}. The background is black.
 * - `furnace`: the white furnace test (a sphere of albedo 1 in a uniform environment of radiance
 *   1). A convex sphere never sees itself, so every path leaving it escapes to the environment and
 *   the radiance leaving it is exactly 1 at every bounce count.
 * - `veach`: Veach's multiple-importance test scene (Veach's thesis, 1997, ch. 9, fig. 9.2): four
 *   glossy plates (the modified Phong BRDF, core/sampling/phongLobe) from sharp to rough, each
 *   tilted so that the camera sees a row of four lights reflected in it; the lights are squares of
 *   very different size and equal power (L · area the same for all four).
 *
 * Units are arbitrary; world space is z-up, as in every scene of the app.
 */
import { makeRectLight, type RectLight } from '../lights/rectLight';
import { examGrid, gridRange, type TextureGrid } from '../texture/grid';
import { normalize, sub, vec3, type Vec3 } from '../vec3';

export const RENDER_SCENES = ['exam', 'furnace', 'veach'] as const;
export type RenderSceneId = (typeof RENDER_SCENES)[number];

export type TextureFilter = 'bilinear' | 'nearest';

/** A one-sided rectangular emitter of uniform radiance L on its normal's side. */
export interface SceneLight {
  rect: RectLight;
  L: number;
}

/** A glossy rectangle: the modified Phong BRDF f = ks (e + 2)/(2π) cosᵉα, α from the mirror direction. */
export interface Plate {
  rect: RectLight;
  exponent: number;
  ks: number;
}

/** The sphere: uniform albedo, or a texture grid whose value sets the albedo by {@link texelAlbedo}. */
export interface SceneSphere {
  center: Vec3;
  radius: number;
  albedo: number;
  texture: TextureGrid | null;
  filter: TextureFilter;
  /** The texture's smallest and largest value (for the albedo map). */
  texMin: number;
  texMax: number;
}

/** Everything the renderer intersects and shades. */
export interface RenderScene {
  id: RenderSceneId;
  /** The Lambertian floor z = 0 (normal +z) with this albedo, or null for no floor. */
  floorAlbedo: number | null;
  sphere: SceneSphere | null;
  lights: SceneLight[];
  plates: Plate[];
  /** Radiance arriving from every direction that hits nothing (0: a black background). */
  environment: number;
}

/** The parameters of the exam scene: the area-light, ray–sphere and texture scenes' own. */
export interface ExamSceneParams {
  rho: number;
  lc: Vec3;
  /** Light width and height. */
  ls: readonly [number, number];
  tilt: number;
  L: number;
  c: Vec3;
  r: number;
  grid: TextureGrid;
  filter: TextureFilter;
}

/**
 * The defaults: the area-light scene's opening light (lc = (0, −0.5, 2), 1 × 1, tilted −30°, L = 1)
 * over its floor of albedo 0.8, the ray–sphere scene's unit sphere at the origin (half sunk into
 * the floor, a dome) and the exam's 5 × 5 texture grid, filtered bilinearly.
 */
export const EXAM_DEFAULTS: ExamSceneParams = {
  rho: 0.8,
  lc: [0, -0.5, 2],
  ls: [1, 1],
  tilt: -30,
  L: 1,
  c: [0, 0, 0],
  r: 1,
  grid: examGrid(),
  filter: 'bilinear',
};

/** Darkest and brightest albedo the texture maps to (so no texel is black or a perfect mirror of light). */
export const TEXEL_ALBEDO_MIN = 0.2;
export const TEXEL_ALBEDO_MAX = 0.8;

/**
 * The sphere's albedo at a texel value: the value's place in the grid's range, mapped linearly
 * onto [0.2, 0.8] (a constant grid gives the middle, 0.5).
 */
export function texelAlbedo(value: number, min: number, max: number): number {
  const t = max > min ? (value - min) / (max - min) : 0.5;
  const s = t < 0 ? 0 : t > 1 ? 1 : t;
  return TEXEL_ALBEDO_MIN + (TEXEL_ALBEDO_MAX - TEXEL_ALBEDO_MIN) * s;
}

/** The exam scene from its parameters (see the module comment). */
export function examScene(p: ExamSceneParams = EXAM_DEFAULTS): RenderScene {
  const { min, max } = gridRange(p.grid);
  return {
    id: 'exam',
    floorAlbedo: p.rho,
    sphere: {
      center: p.c,
      radius: p.r,
      albedo: 0.5,
      texture: p.grid,
      filter: p.filter,
      texMin: min,
      texMax: max,
    },
    lights: [{ rect: makeRectLight(p.lc, p.ls[0], p.ls[1], p.tilt), L: p.L }],
    plates: [],
    environment: 0,
  };
}

/** The white furnace: a unit sphere of albedo 1 at the origin in an environment of radiance 1. */
export function furnaceScene(): RenderScene {
  return {
    id: 'furnace',
    floorAlbedo: null,
    sphere: {
      center: [0, 0, 0],
      radius: 1,
      albedo: 1,
      texture: null,
      filter: 'bilinear',
      texMin: 0,
      texMax: 1,
    },
    lights: [],
    plates: [],
    environment: 1,
  };
}

/** The camera of the veach scene (shared with its default view, so the reflections line up). */
export const VEACH_EYE: Vec3 = [0, -7, 2.2];
/** Phong exponents of the four plates, sharp (nearest the camera) to rough. */
export const VEACH_EXPONENTS = [20000, 2000, 150, 10] as const;
/** Sides of the four square lights, left to right: each 3–4 times the last. */
export const VEACH_LIGHT_SIDES = [0.03, 0.12, 0.45, 1.6] as const;
/** The power of each light, as L · area (equal for all four). */
export const VEACH_LIGHT_POWER = 0.3;

/**
 * The tilt (degrees, about the x axis, core/lights/rectLight's convention) whose rectangle has the
 * unit normal (0, ny, nz): n = (0, sin t, −cos t).
 */
function tiltFacing(n: Vec3): number {
  return (Math.atan2(n[1], -n[2]) * 180) / Math.PI;
}

/**
 * Veach's scene: the lights in a row along x at y = 2.5, z = 3.2; four 4 × 0.5 plates at y from
 * −1.5 to 1.2, rising, each plate's normal the bisector of the directions to the camera and to
 * the row of lights, so every plate mirrors the row towards the camera.
 */
export function veachScene(): RenderScene {
  const lightRow: Vec3 = [0, 2.5, 3.2];
  const aim: Vec3 = [0, -0.2, 0.2];
  const lights = VEACH_LIGHT_SIDES.map((side, k) => {
    const centre = vec3(-1.65 + 1.1 * k, lightRow[1], lightRow[2]);
    const n = normalize(sub(aim, centre));
    const rect = makeRectLight(centre, side, side, tiltFacing([0, n[1], n[2]]));
    return { rect, L: VEACH_LIGHT_POWER / (side * side) };
  });
  const plates = VEACH_EXPONENTS.map((exponent, k) => {
    const centre = vec3(0, -1.5 + 0.9 * k, 0.25 * k);
    const toEye = normalize(sub(VEACH_EYE, centre));
    const toLight = normalize(sub(lightRow, centre));
    const n = normalize([0, toEye[1] + toLight[1], toEye[2] + toLight[2]]);
    return { rect: makeRectLight(centre, 4, 0.5, tiltFacing(n)), exponent, ks: 0.8 };
  });
  return { id: 'veach', floorAlbedo: null, sphere: null, lights, plates, environment: 0 };
}

/** A camera: eye, the point looked at, and the vertical field of view in degrees. */
export interface View {
  eye: Vec3;
  look: Vec3;
  fov: number;
}

/** Each preset's opening view. */
export function defaultView(id: RenderSceneId): View {
  if (id === 'furnace') return { eye: [0, -4, 0.5], look: [0, 0, 0], fov: 40 };
  if (id === 'veach') return { eye: VEACH_EYE, look: [0, 0.4, 0.9], fov: 42 };
  return { eye: [0, -6, 3.5], look: [0, 0, 0.6], fov: 45 };
}

/** A scene as plain data (what crosses to a worker): which preset, and the exam scene's parameters. */
export interface RenderSpec {
  scene: RenderSceneId;
  exam: ExamSceneParams;
}

/** The scene a spec describes. */
export function buildScene(spec: RenderSpec): RenderScene {
  if (spec.scene === 'furnace') return furnaceScene();
  if (spec.scene === 'veach') return veachScene();
  return examScene(spec.exam);
}
