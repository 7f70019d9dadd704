/**
 * The Šidák correction, on its own: the t-tests (./ttest, ./welchMap) use it without the χ² test's
 * incomplete gamma function (@stdlib, about 19 kB gzipped), which a page's t-test line would
 * otherwise download with it.
 */

/**
 * Šidák-corrected per-test significance: when m independent tests are run and we want the chance
 * of any false rejection to be α overall, each test uses 1 − (1 − α)^(1/m).
 * Computed as −expm1(log1p(−α)/m), exact for tiny α and large m.
 * Domain: α ∈ [0, 1], m ≥ 1 (m < 1 is treated as 1). Source: Šidák (1967), JASA 62(318).
 */
export function sidakAlpha(alpha: number, m: number): number {
  if (!(alpha > 0)) return 0;
  if (alpha >= 1) return 1;
  const mm = m >= 1 ? m : 1;
  return -Math.expm1(Math.log1p(-alpha) / mm);
}
