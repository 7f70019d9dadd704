/**
 * URL parameters of #/render (see docs/urls.md): the preset (`scene`), the direct-light estimator
 * (`strategy`) and path length (`bounces`); the exam scene's objects with the area-light, ray–sphere
 * and texture scenes' own parameters (rho, lc, ls, tilt, L; c, r; grid, filter); the camera (eye,
 * look, fov: empty means the preset's own view); the image (res, spp, seed, renderer: gpu or cpu); the
 * inspected pixel (px = i,j, column i and row j from the top left) and its sample count pn; the
 * folds' own choices (`et`, the equal-time budget; `vs`, the strategy the Welch map compares
 * with); and the progressive run's timeline, whose time is samples per pixel: `play` (0 holds the
 * render) and `t` (with play=0, the samples per pixel it renders to and holds at; pausing writes it).
 */
import { BIASES } from '../../core/render/bias';
import type { ParamSchema, ParamValues } from '../../kit/params';
import { EXAM_GRID_TEXT } from '../../core/texture/grid';
import { RENDER_SCENES, EXAM_DEFAULTS } from '../../core/render/scene';
import { STRATEGIES, type Strategy } from '../../core/render/directLight';
import { MAX_BOUNCES, MIN_BOUNCES } from '../../core/render/pathTrace';
import { DEFAULT_PN } from '../../core/render/inspector';
import { timelineParams } from '../../kit/timeline';

const BIG = 1e6;

/**
 * The strategies whose runs of a few samples give nearly normal pixel values, each sample aiming
 * at the light: the ones the Welch map compares. Uniform, cosine and BSDF sampling find a small
 * light only now and then, so most of their short runs see it never or once.
 */
export const LIGHT_SAMPLING = [
  'area',
  'solid-angle',
  'mis-balance',
  'mis-power',
] as const satisfies readonly Strategy[];

/** The equal-time fold's budgets per strategy, in milliseconds. */
export const EQUAL_TIME_BUDGETS = ['250', '1000', '4000'] as const;

/** Smallest and largest image side, in pixels. */
export const MIN_RES = 32;
export const MAX_RES = 512;
/** Most samples per pixel a run takes. */
export const MAX_SPP = 65536;

export const schema = {
  scene: { kind: 'enum', default: 'exam', values: RENDER_SCENES, label: 'scene' },
  strategy: {
    kind: 'enum',
    default: 'mis-power',
    values: STRATEGIES,
    aliases: { solid: 'solid-angle', mis: 'mis-power', balance: 'mis-balance', power: 'mis-power' },
    label: 'direct-light strategy',
  },
  bias: {
    kind: 'enum',
    default: 'none',
    values: BIASES,
    label: 'biased variant (for the t-test)',
  },
  bounces: {
    kind: 'number',
    default: 1,
    min: MIN_BOUNCES,
    max: MAX_BOUNCES,
    integer: true,
    label: 'bounces',
  },
  rho: { kind: 'number', default: EXAM_DEFAULTS.rho, min: 0, max: 1, label: 'floor albedo ρ' },
  lc: { kind: 'vec3', default: EXAM_DEFAULTS.lc, min: -BIG, max: BIG, label: 'light centre' },
  ls: {
    kind: 'list',
    default: EXAM_DEFAULTS.ls,
    minItems: 2,
    maxItems: 2,
    min: 0,
    max: BIG,
    label: 'light size w,h',
  },
  tilt: { kind: 'number', default: EXAM_DEFAULTS.tilt, min: -360, max: 360, label: 'light tilt (degrees)' },
  L: { kind: 'number', default: EXAM_DEFAULTS.L, min: 0, max: BIG, label: 'radiance L' },
  c: { kind: 'vec3', default: EXAM_DEFAULTS.c, min: -BIG, max: BIG, label: 'sphere centre C' },
  r: { kind: 'number', default: EXAM_DEFAULTS.r, min: 1e-6, max: BIG, label: 'sphere radius r' },
  grid: { kind: 'string', default: EXAM_GRID_TEXT, maxLength: 4000, label: 'texel grid, rows top to bottom' },
  filter: { kind: 'enum', default: 'bilinear', values: ['bilinear', 'nearest'], label: 'texture filter' },
  eye: { kind: 'list', default: null, minItems: 3, maxItems: 3, min: -BIG, max: BIG, label: 'camera eye' },
  look: {
    kind: 'list',
    default: null,
    minItems: 3,
    maxItems: 3,
    min: -BIG,
    max: BIG,
    label: 'point looked at',
  },
  fov: {
    kind: 'list',
    default: null,
    minItems: 1,
    maxItems: 1,
    min: 1,
    max: 179,
    label: 'field of view (degrees)',
  },
  res: {
    kind: 'number',
    default: 128,
    min: MIN_RES,
    max: MAX_RES,
    integer: true,
    label: 'image side (pixels)',
  },
  spp: { kind: 'number', default: 64, min: 1, max: MAX_SPP, integer: true, label: 'samples per pixel' },
  seed: { kind: 'number', default: 1, min: 0, max: 4294967295, integer: true, label: 'seed' },
  renderer: {
    kind: 'enum',
    default: 'gpu',
    values: ['gpu', 'cpu'],
    label: 'renderer (gpu: WebGL2 float32; cpu: float64 in workers)',
  },
  px: {
    kind: 'list',
    default: null,
    minItems: 2,
    maxItems: 2,
    min: 0,
    max: MAX_RES - 1,
    label: 'inspected pixel i,j',
  },
  pn: {
    kind: 'number',
    default: DEFAULT_PN,
    min: 2,
    max: 1 << 20,
    integer: true,
    label: 'inspector samples',
  },
  et: {
    kind: 'enum',
    default: '1000',
    values: EQUAL_TIME_BUDGETS,
    label: 'equal-time budget per strategy (ms)',
  },
  vs: {
    kind: 'enum',
    default: 'auto',
    values: ['auto', ...LIGHT_SAMPLING],
    label:
      'the strategy the Welch map compares with (auto: area, or solid-angle when the page samples by area)',
  },
  play: { kind: 'bool', default: true, label: 'render running' },
  t: { ...timelineParams({ max: MAX_SPP, integer: true }).t, label: 'samples per pixel to hold at (play=0)' },
} as const satisfies ParamSchema;

export type RenderParams = ParamValues<typeof schema>;

/** The strategy the Welch map compares the page's with: `vs`, or for `auto` one that is not the page's. */
export function welchOther(vs: RenderParams['vs'], strategy: Strategy): Strategy {
  if (vs !== 'auto') return vs;
  return strategy === 'area' ? 'solid-angle' : 'area';
}
