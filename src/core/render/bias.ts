/**
 * Deliberately biased variants of the direct-light estimator, for the t-test to catch (Nori's
 * `ttest`; Jung, Hanika and Dachsbacher, JCGT 2020): an estimator is tested against its reference,
 * and a test is only worth its name if it rejects an estimator that is wrong.
 *
 * - `no-cos-l`: area sampling with the slip the exam's Q6(a) guards against, the solid angle of a
 *   light element taken as dA/r² instead of cos θ_l dA/r²; each area-sampled term is divided by
 *   cos θ_l ≤ 1, so the estimate is too bright (other techniques are unchanged);
 * - `clamp`: every term clamped at CLAMP_MAX, the firefly suppression of production renderers;
 *   it trades variance for a bias wherever terms above the clamp have any probability.
 */
export const BIASES = ['none', 'no-cos-l', 'clamp'] as const;
export type Bias = (typeof BIASES)[number];

/** The clamp of the `clamp` variant, in units of radiance. */
export const CLAMP_MAX = 0.5;

/** A term of technique `technique` with light cosine `cosThetaL`, as the variant `bias` computes it. */
export function biasedTerm(bias: Bias, term: number, technique: string, cosThetaL: number): number {
  if (bias === 'clamp') return Math.min(term, CLAMP_MAX);
  if (bias === 'no-cos-l' && technique === 'area' && cosThetaL > 0) return term / cosThetaL;
  return term;
}

/** Whether variant `bias` changes an estimator that uses `strategy` (no-cos-l needs area sampling). */
export function biasApplies(bias: Bias, strategy: string): boolean {
  return bias === 'clamp' || (bias === 'no-cos-l' && strategy === 'area');
}
