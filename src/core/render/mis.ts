/**
 * Veach's heuristics for multiple importance sampling (Veach's thesis, 1997, ch. 9; pbrt-v4
 * §2.2.3): a sample drawn by technique a, whose density there is pa, with the other technique's
 * density pb at the same point (both per unit solid angle), gets the weight
 *
 *     balance:  w = pa / (pa + pb)          power (β = 2):  w = pa² / (pa² + pb²).
 *
 * With nₐ = n_b samples from each, F = Σ_a (1/nₐ) Σᵢ w f / pa is unbiased: the weights of the two
 * techniques sum to 1 wherever either density is positive.
 */

export type MisHeuristic = 'balance' | 'power';

/** The weight of a sample drawn by the technique of density pa against one of density pb (0 where pa = 0). */
export function misWeight(heuristic: MisHeuristic, pa: number, pb: number): number {
  if (!(pa > 0)) return 0;
  if (!(pb > 0)) return 1;
  if (heuristic === 'balance') return pa / (pa + pb);
  // divide through by the larger density first, so neither square overflows or underflows
  const m = Math.max(pa, pb);
  const a = pa / m,
    b = pb / m;
  return (a * a) / (a * a + b * b);
}
