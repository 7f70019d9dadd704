/** The six practice questions: metadata and the variant generator of each (pure). */
import { QUESTION_IDS, type QuestionId, type Variant } from './model';
import { q1Variant } from './q1';
import { q2Variant } from './q2';
import { q3Variant } from './q3';
import { q4Variant } from './q4';
import { q5Variant } from './q5';
import { q6Variant } from './q6';

export interface QuestionInfo {
  id: QuestionId;
  n: number;
  title: string;
  blurb: string;
  generate: (seed: number) => Variant;
}

export const QUESTIONS: readonly QuestionInfo[] = [
  {
    id: 'q1',
    n: 1,
    title: 'Sampling a hemisphere PDF by inversion',
    blurb: 'Normalize k cosᵐθ e^(aφ), its marginals, CDFs and inversion formulas.',
    generate: q1Variant,
  },
  {
    id: 'q2',
    n: 2,
    title: 'Monte Carlo estimators on the hemisphere',
    blurb: 'Uniform and importance-sampled estimates from given directions; which has zero variance.',
    generate: q2Variant,
  },
  {
    id: 'q3',
    n: 3,
    title: 'Texture lookup',
    blurb: 'Nearest and bilinear lookup on a texel grid, and the spherical (u, v) of a point.',
    generate: q3Variant,
  },
  {
    id: 'q4',
    n: 4,
    title: 'Monte Carlo integration in 1D',
    blurb: 'The exact integral, the uniform and the importance-sampled estimate from given samples.',
    generate: q4Variant,
  },
  {
    id: 'q5',
    n: 5,
    title: 'Ray–sphere intersection',
    blurb: 'The quadratic, its discriminant, the roots, the hit and the case.',
    generate: q5Variant,
  },
  {
    id: 'q6',
    n: 6,
    title: 'Solid angle and area lights',
    blurb: 'dω = dA cos θ_l / r² for a patch, and the area-sampling estimator from given points.',
    generate: q6Variant,
  },
];

export function isQuestionId(s: string): s is QuestionId {
  return (QUESTION_IDS as readonly string[]).includes(s);
}

export function questionInfo(id: QuestionId): QuestionInfo {
  return QUESTIONS.find((q) => q.id === id)!;
}

/** Seed of the k-th variant of a question on a worksheet with base seed `seed` (wraps at 2³²). */
export function sheetSeed(seed: number, k: number): number {
  return (seed + k) >>> 0;
}
