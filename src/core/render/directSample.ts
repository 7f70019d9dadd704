/**
 * One sample of the direct-light estimator written out in full (what the pixel inspector shows as
 * a row): the technique, the direction and the light point it reached, f, L, cos θ, cos θ_l, r²,
 * the density in its own measure and in solid angle, the MIS weight and the term; and the
 * estimator's reusable buffers.
 */
import { newHit, type Hit } from './intersect';
import type { EmitterSample, LightFrames } from './lightSampling';
import type { Vertex } from './material';

/** The technique one sample was drawn by. */
export type Technique = 'uniform' | 'cosine' | 'bsdf' | 'area' | 'solid-angle';

/** One direct-light sample, in full: what was drawn, what it saw, its densities, weight and term. */
export interface DirectSample {
  technique: Technique;
  /** Unit direction ωᵢ. */
  dx: number;
  dy: number;
  dz: number;
  /** The point on a light the sample reached (NaN when it reached none). */
  lx: number;
  ly: number;
  lz: number;
  /** What the sample reached: a light's index, −1 the environment, −2 nothing that emits. */
  light: number;
  f: number;
  /** Emitted radiance arriving along ωᵢ (after visibility). */
  L: number;
  cosTheta: number;
  /** cos θ_l at the light point and r² = |x − p|² (NaN without a light point). */
  cosThetaL: number;
  r2: number;
  /** The density in the technique's own measure, that measure, and converted to solid angle. */
  pdf: number;
  measure: 'solid-angle' | 'area';
  pdfSolidAngle: number;
  /** The MIS weight (1 for a single technique). */
  weight: number;
  /** The estimate this sample makes of L_d. */
  term: number;
}

export function newDirectSample(): DirectSample {
  return {
    technique: 'uniform',
    dx: 0,
    dy: 0,
    dz: 1,
    lx: NaN,
    ly: NaN,
    lz: NaN,
    light: -2,
    f: 0,
    L: 0,
    cosTheta: 0,
    cosThetaL: NaN,
    r2: NaN,
    pdf: 0,
    measure: 'solid-angle',
    pdfSolidAngle: 0,
    weight: 1,
    term: 0,
  };
}

/** Reused buffers of the estimator (one per thread of work). */
export interface DirectScratch {
  hit: Hit;
  dir: Float64Array;
  buf: Float64Array;
  emitter: EmitterSample;
  /** The light frames and the vertex they were built for. */
  frames: LightFrames | null;
  framesFor: Vertex | null;
}

export function newDirectScratch(): DirectScratch {
  return {
    hit: newHit(),
    dir: new Float64Array(3),
    buf: new Float64Array(3),
    emitter: { light: -1, x: 0, y: 0, z: 0, pdf: 0 },
    frames: null,
    framesFor: null,
  };
}
