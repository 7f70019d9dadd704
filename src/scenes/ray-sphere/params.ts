/**
 * URL parameters of #/ray-sphere (see docs/urls.md): the ray o + t d, the sphere
 * (centre C, radius r; the URL parameter for C is `c`), the evaluation method and the arithmetic
 * (`precision`: f64, or f32 — IEEE single precision, every operation rounded, as a GPU). Vectors are
 * "x,y,z" in z-up world space. The sweep animation: `sweep` (the origin moves across the ray, or
 * the direction turns), `extent` (how far, in radii / angular radii either side) and the shared
 * timeline's `t` ∈ [0, 1] (0.5, the default, is the configuration typed in o, d) and `play`.
 * The radius may be typed ≤ 0 (it is in range here so the scene itself can explain why that is
 * not a sphere and fall back); non-numbers are rejected by the shell with a notice.
 */
import type { ParamSchema, ParamValues } from '../../kit/params';
import { timelineParams } from '../../kit/timeline';

const BIG = 1e12;

export const schema = {
  o: { kind: 'vec3', default: [-3, -1.2, 0.6], min: -BIG, max: BIG, label: 'ray origin o' },
  d: { kind: 'vec3', default: [1, 0.4, -0.15], min: -BIG, max: BIG, label: 'ray direction d' },
  c: { kind: 'vec3', default: [0, 0, 0], min: -BIG, max: BIG, label: 'sphere centre C' },
  r: { kind: 'number', default: 1, min: -BIG, max: BIG, label: 'sphere radius r' },
  method: {
    kind: 'enum',
    default: 'stable',
    values: ['stable', 'naive'],
    aliases: { robust: 'stable', textbook: 'naive' },
    label: 'method',
  },
  precision: {
    kind: 'enum',
    default: 'f64',
    values: ['f64', 'f32'],
    aliases: { double: 'f64', float64: 'f64', single: 'f32', float32: 'f32', float: 'f32' },
    label: 'arithmetic (f64 double, f32 single precision as on a GPU)',
  },
  sweep: {
    kind: 'enum',
    default: 'offset',
    values: ['offset', 'rotate'],
    aliases: { shift: 'offset', move: 'offset', turn: 'rotate', rotation: 'rotate' },
    label: 'sweep mode',
  },
  extent: {
    kind: 'number',
    default: 2.5,
    min: 0.05,
    max: 1000,
    label: 'sweep extent (radii, or angular radii when rotating)',
  },
  ...timelineParams({ max: 1, default: 0.5 }),
} as const satisfies ParamSchema;

export type RaySphereParams = ParamValues<typeof schema>;

/** A named configuration; `params` is a patch applied to the URL. */
export interface Preset {
  id: string;
  label: string;
  /** One line: what the preset shows. */
  what: string;
  params: Partial<RaySphereParams>;
}

/** One preset per case (exam Q5). Exact binary values so the tangent one is exactly tangent. */
export const CASE_PRESETS: readonly Preset[] = [
  {
    id: 'two-hits',
    label: 'Two hits',
    what: 'The ray enters and leaves: two roots t₀ < t₁, both ≥ 0; the hit is t₀.',
    params: { o: [-3, 0.3, 0.2], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
  },
  {
    id: 'miss',
    label: 'Miss',
    what: 'The line passes the sphere: Δ < 0, no real root.',
    params: { o: [-3, 1.5, 0.2], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
  },
  {
    id: 'tangent',
    label: 'Tangent',
    what: 'The line touches the sphere: Δ = 0 exactly, one double root.',
    params: { o: [-5, 1, 0], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
  },
  {
    id: 'inside',
    label: 'Origin inside',
    what: 'One root behind (t₀ < 0), one ahead: the hit is t₁, the exit point.',
    params: { o: [0.2, -0.3, 0.1], d: [1, 0.5, 0], c: [0, 0, 0], r: 1 },
  },
  {
    id: 'behind',
    label: 'Sphere behind',
    what: 'Δ > 0 but both roots are negative: the line meets the sphere behind the origin, so no hit.',
    params: { o: [3, 0.3, 0.2], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
  },
];

/**
 * Presets that break the textbook form. The URL carries exact doubles (String(x) round-trips),
 * e.g. 1.0000000000000002 = 1 + 2⁻⁵² and 0.9999999999999999 = 1 − 2⁻⁵³.
 */
export const PRECISION_PRESETS: readonly Preset[] = [
  {
    id: 'far',
    label: 'Small sphere 10⁸ r away',
    what: 'c = 10¹⁶ − 1 rounds to 10¹⁶, so b² − 4ac = 0: the textbook form reports a tangent and misplaces the hit by 0.87 r.',
    params: { o: [0, 0, 0], d: [1, 5e-9, 0], c: [1e8, 0, 0], r: 1 },
  },
  {
    id: 'grazing',
    label: 'Grazing ray at 10⁵',
    what: 'The ray passes 10⁻⁵ r inside the rim from 10⁵ r away: b² and 4ac (both ≈ 4·10¹⁰) agree to 15 digits, so the textbook Δ ≈ 8·10⁻⁵ is 5% off and its roots move by 10⁻⁴.',
    params: { o: [-1e5, 0.99999, 0], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
  },
  {
    id: 'ulp-past',
    label: 'One ulp past tangent',
    what: 'The ray passes at 1 + 2⁻⁵² from the centre: exactly a miss. The textbook form rounds c and reports a tangent hit.',
    params: { o: [-5, 1.0000000000000002, 0], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
  },
  {
    id: 'ulp-inside',
    label: 'One ulp inside tangent',
    what: 'At 1 − 2⁻⁵³ from the centre there are two hits 2⁻²⁵ apart; the textbook form merges them into one.',
    params: { o: [-5, 0.9999999999999999, 0], d: [1, 0, 0], c: [0, 0, 0], r: 1 },
  },
];
