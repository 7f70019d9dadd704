/**
 * URL parameters of #/area-light (see docs/urls.md): the shading point p on a floor
 * (normal +z), a rectangular emitter (centre lc, size ls = w,h, tilt about its x axis, radiance L),
 * the floor albedo rho, an optional occluder, the sampling strategy, n and seed. The Q6(a) patch
 * (pu, pv, psize, ptilt) is an addition to the contract (it only grows).
 *
 * The defaults open on Q6's point: the light hangs off to one side, tilted 30° (not parallel to the
 * floor) with its emitting face towards the opening camera, and the patch is tilted on it, so cos θ at the point and cos θₗ at the light differ at
 * every sample, and dA⊥ = dA cos θₗ is visibly smaller than dA. The plain setup (the light overhead
 * and parallel to the floor, the patch flat on it) is one click away: EXAM_PRESET.
 */
import type { ParamSchema, ParamValues } from '../../kit/params';
import { timelineParams } from '../../kit/timeline';

/** Longest animation (samples); the same constant as model.ANIM_MAX (kept here: params must not import the model). */
const ANIM_SAMPLES = 1024;

const BIG = 1e9;

export const schema = {
  p: { kind: 'vec3', default: [0, 0, 0], min: -BIG, max: BIG, label: 'shading point p' },
  lc: { kind: 'vec3', default: [0, -0.5, 2], min: -BIG, max: BIG, label: 'light centre' },
  ls: { kind: 'list', default: [1, 1], minItems: 2, maxItems: 2, min: 0, max: BIG, label: 'light size w,h' },
  tilt: { kind: 'number', default: -30, min: -360, max: 360, label: 'light tilt (degrees)' },
  L: { kind: 'number', default: 1, min: 0, max: 1e6, label: 'radiance L' },
  rho: { kind: 'number', default: 0.8, min: 0, max: 1, label: 'albedo ρ' },
  occluder: { kind: 'bool', default: false, label: 'occluder' },
  strategy: {
    kind: 'enum',
    default: 'area',
    values: ['area', 'solid-angle', 'cosine'],
    aliases: {
      solid: 'solid-angle',
      solidangle: 'solid-angle',
      spherical: 'solid-angle',
      hemisphere: 'cosine',
      cos: 'cosine',
    },
    label: 'strategy',
  },
  n: { kind: 'number', default: 1024, min: 1, max: 1000000, integer: true, label: 'samples n' },
  seed: { kind: 'number', default: 1, min: 0, max: 4294967295, integer: true, label: 'seed' },
  pu: { kind: 'number', default: 0.3, min: 0, max: 1, label: 'patch position u on the light' },
  pv: { kind: 'number', default: 0.6, min: 0, max: 1, label: 'patch position v on the light' },
  psize: { kind: 'number', default: 0.25, min: 1e-6, max: 2, label: 'patch side' },
  ptilt: {
    kind: 'number',
    default: -10,
    min: -89,
    max: 89,
    label: 'patch tilt (degrees, relative to the light)',
  },
  // The animation: t = samples arrived (0 … min(n, 1024)); the default shows them all.
  ...timelineParams({ max: ANIM_SAMPLES, default: ANIM_SAMPLES, integer: true }),
} as const satisfies ParamSchema;

export type AreaLightParams = ParamValues<typeof schema>;

/** A named configuration; `params` is a patch applied to the URL. */
export interface Preset {
  id: string;
  label: string;
  /** One line: what the preset shows (who wins and why). */
  what: string;
  params: Partial<AreaLightParams>;
}

/** The plain geometry: a 1 × 1 light 2 above the point and parallel to the floor. */
const OVERHEAD = { p: [0, 0, 0], lc: [0, 0, 2], ls: [1, 1], tilt: 0 } satisfies Partial<AreaLightParams>;

/**
 * The exam's configuration. Q6 gives no numbers; this is the plain setup its figure and answers
 * assume: a 1 × 1 light 2 above the point, parallel to the floor, the Q6(a) patch flat on it,
 * sampled uniformly by area as in (c). It was the scene's opening before the tilted one.
 */
export const EXAM_PRESET: Preset = {
  id: 'exam',
  label: 'The exam’s configuration',
  what: 'The light 2 above the point and parallel to the floor, the patch flat on it, uniform area sampling as in (c): here cos θ = cos θₗ at every sample.',
  params: { ...OVERHEAD, pu: 0.3, pv: 0.6, psize: 0.25, ptilt: 0, strategy: 'area', occluder: false },
};

/** The opening view (the defaults): a tilted light beside the point and a tilted patch. */
export const OPENING_PRESET: Preset = {
  id: 'opening',
  label: 'The opening (tilted)',
  what: 'The light tilted 30° beside the point and the patch tilted on it: cos θ ≠ cos θₗ, and dA⊥ = dA cos θₗ < dA.',
  params: {
    p: [...schema.p.default],
    lc: [...schema.lc.default],
    ls: [...schema.ls.default],
    tilt: schema.tilt.default,
    pu: schema.pu.default,
    pv: schema.pv.default,
    psize: schema.psize.default,
    ptilt: schema.ptilt.default,
    strategy: schema.strategy.default,
    occluder: schema.occluder.default,
  },
};

/** The value of each parameter a preset sets equals the current one. */
export function presetActive(pr: Preset, values: AreaLightParams): boolean {
  return Object.entries(pr.params).every(([k, v]) => {
    const cur = values[k as keyof AreaLightParams];
    return Array.isArray(v) && Array.isArray(cur)
      ? v.length === cur.length && v.every((x, i) => Object.is(x, cur[i]))
      : Object.is(v, cur);
  });
}

export const PRESETS: readonly Preset[] = [
  EXAM_PRESET,
  OPENING_PRESET,
  {
    id: 'overhead',
    label: 'Overhead',
    what: 'A 1 × 1 light 2 units above the point: all three strategies work; solid-angle sampling is nearly noise-free.',
    params: OVERHEAD,
  },
  {
    id: 'near',
    label: 'Near',
    what: 'A big light just above the floor: r² varies wildly over it, so area sampling is noisy; cosine sampling is good.',
    params: { p: [0, 0, 0], lc: [0, 0, 0.25], ls: [2, 2], tilt: 0 },
  },
  {
    id: 'far',
    label: 'Far',
    what: 'A small, distant light: cosine sampling almost never hits it; area and solid-angle sampling are nearly exact.',
    params: { p: [0, 0, 0], lc: [0, 0, 10], ls: [1, 1], tilt: 0 },
  },
  {
    id: 'grazing',
    label: 'Grazing',
    what: 'A light low on the horizon: cos θ is tiny, and both light strategies spend samples where cos θ ≈ 0.',
    params: { p: [0, 0, 0], lc: [0, 3, 0.6], ls: [2, 1], tilt: -80 },
  },
  {
    id: 'tilted',
    label: 'Tilted',
    what: 'A light tilted 45° off to the side: cos θₗ varies over the light.',
    params: { p: [0, 0, 0], lc: [0, 1, 1.5], ls: [1.5, 1], tilt: -45 },
  },
  {
    id: 'horizon',
    label: 'Partly below the horizon',
    what: 'A vertical light whose lower part is below the floor: Lambert’s formula is clipped to z ≥ 0.',
    params: { p: [0, 0, 0], lc: [0, 1, 0.2], ls: [1, 1], tilt: -90 },
  },
  {
    id: 'away',
    label: 'Facing away',
    what: 'The light faces up: its back is black, so Lₒ = 0 exactly, and every estimator returns 0.',
    params: { ...OVERHEAD, tilt: 180 },
  },
];
