/**
 * URL parameters of the hemisphere scene (contract: `..docs/urls.md`, route `#/hemisphere`).
 *
 * Contract parameters: lobe, exponent, pdf, jacobian, f, n, seed.
 * Added by this scene (the contract only grows): `points`, the point set fed to the warp; `anim`,
 * which animation the shared timeline plays (`warp`: the (ξ₁, ξ₂) points and grid travel from the
 * unit square to the hemisphere; `grow`: the samples appear, 1 → N); `t` ∈ [0, 1] (default 1, the
 * finished figure) and `play` (shared timeline); `cell` = i,j, the stratum of the 8 × 8 grid of the
 * unit square the figure follows onto the hemisphere (ξ₁ ∈ [i/8, (i+1)/8), ξ₂ ∈ [j/8, (j+1)/8); none by
 * default).
 */
import type { ParamSchema, ParamValues } from '../../kit/params';
import { timelineParams } from '../../kit/timeline';

export const LOBES = ['exam', 'uniform', 'cosine', 'phong', 'custom'] as const;
export type LobeId = (typeof LOBES)[number];

export const ANIMS = ['warp', 'grow'] as const;

export const POINT_SETS = ['independent', 'stratified', 'halton', 'sobol'] as const;

/** Largest sample count: the 3D view animates up to this many points. */
export const MAX_N = 1_000_000;

export const schema = {
  lobe: {
    kind: 'enum',
    default: 'exam',
    values: LOBES,
    aliases: {
      key: 'exam',
      q1: 'exam',
      cos: 'cosine',
      'cosine-weighted': 'cosine',
      typed: 'custom',
      user: 'custom',
    },
    label: 'sampling density',
  },
  exponent: { kind: 'number', default: 8, min: 0, max: 10000, label: 'Phong exponent n' },
  pdf: {
    kind: 'string',
    default: 'cos(theta)^2 * (2 + cos(phi))',
    maxLength: 400,
    label: 'typed density p(θ, φ) per steradian',
    expression: ['theta', 'phi'],
  },
  jacobian: {
    kind: 'enum',
    default: 'correct',
    values: ['correct', 'inverted'],
    aliases: { key: 'inverted', wrong: 'inverted', right: 'correct' },
  },
  f: {
    kind: 'string',
    default: 'cos(theta)',
    maxLength: 400,
    label: 'integrand f(θ, φ)',
    expression: ['theta', 'phi'],
  },
  n: { kind: 'number', default: 20000, min: 1, max: MAX_N, integer: true, label: 'sample count' },
  seed: { kind: 'number', default: 1, min: 0, max: 4294967295, integer: true },
  points: {
    kind: 'enum',
    default: 'independent',
    values: POINT_SETS,
    aliases: { random: 'independent', jittered: 'stratified' },
  },
  anim: {
    kind: 'enum',
    default: 'warp',
    values: ANIMS,
    aliases: { morph: 'warp', growth: 'grow' },
    label: 'animation',
  },
  cell: {
    kind: 'list',
    default: null,
    minItems: 2,
    maxItems: 2,
    min: 0,
    max: 7,
    label: 'followed stratum i,j of the (ξ₁, ξ₂) grid',
  },
  ...timelineParams({ max: 1, default: 1 }),
} as const satisfies ParamSchema;

export type HemisphereSchema = typeof schema;
export type HemisphereParams = ParamValues<HemisphereSchema>;
