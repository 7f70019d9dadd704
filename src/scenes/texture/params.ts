/**
 * URL parameters of the texture scene (contract: `..docs/urls.md`, route `#/texture`).
 *
 * Contract parameters: u, v, grid, align, vflip, wrap, x, y, z, normalize.
 * Added by this scene (the contract only grows): `preset` (where the grid comes from), `size`
 * and `seed` (for the generated presets). They exist because a 64 × 64 grid cannot be written in
 * the `grid` parameter: the shell caps any parameter at 4000 characters.
 */
import type { ParamSchema } from '../../kit/params';
import { EXAM_GRID_TEXT } from '../../core/texture';
import { timelineParams } from '../../kit/timeline';

/** Longest `grid` text the shell will accept in a URL (its MAX_RAW_LENGTH). */
export const GRID_TEXT_MAX = 4000;

export const PATHS = ['line', 'circle'] as const;
export type PathKind = (typeof PATHS)[number];

export const PRESETS = ['grid', 'checker', 'gradient', 'random'] as const;
export type Preset = (typeof PRESETS)[number];

export const schema = {
  u: { kind: 'number', default: 0.4, min: -4, max: 4, label: 'u' },
  v: { kind: 'number', default: 0.24, min: -4, max: 4, label: 'v' },
  grid: {
    kind: 'string',
    default: EXAM_GRID_TEXT,
    maxLength: GRID_TEXT_MAX,
    label: 'texel grid, rows top to bottom',
  },
  align: {
    kind: 'enum',
    default: 'corner',
    values: ['corner', 'center'],
    aliases: { centre: 'center', centers: 'center', corners: 'corner' },
  },
  vflip: { kind: 'bool', default: false },
  wrap: {
    kind: 'enum',
    default: 'clamp',
    values: ['clamp', 'repeat', 'mirror'],
    aliases: { wrap: 'repeat', mirrored: 'mirror', 'clamp-to-edge': 'clamp' },
  },
  x: { kind: 'number', default: 1, min: -1000, max: 1000 },
  y: { kind: 'number', default: 1, min: -1000, max: 1000 },
  z: { kind: 'number', default: Math.SQRT2, min: -1000, max: 1000 },
  normalize: { kind: 'bool', default: true },
  preset: {
    kind: 'enum',
    default: 'grid',
    values: PRESETS,
    aliases: { exam: 'grid', custom: 'grid', checkerboard: 'checker' },
  },
  size: { kind: 'number', default: 8, min: 2, max: 64, integer: true },
  seed: { kind: 'number', default: 1, min: 0, max: 4294967295, integer: true },
  // the animation: the query travels from (u, v) to (u2, v2) on a line, or round the
  // circle that has them as the ends of a diameter; t ∈ [0, 1] is the position on the path
  path: { kind: 'enum', default: 'line', values: PATHS, label: 'query path' },
  u2: { kind: 'number', default: 0.85, min: -4, max: 4, label: 'path end u' },
  v2: { kind: 'number', default: 0.8, min: -4, max: 4, label: 'path end v' },
  ...timelineParams({ max: 1 }),
} as const satisfies ParamSchema;

export type TextureSchema = typeof schema;
