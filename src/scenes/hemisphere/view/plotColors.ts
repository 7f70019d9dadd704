/**
 * The colours of the scene's plots, from the shared palette (src/ui/palette: each ≥ 3 : 1 on
 * the page and panel backgrounds in both themes, and told apart under colour-vision deficiencies).
 * Plot resolves the var() when it draws, and again when the theme changes.
 */
import { SERIES, STRATEGY_COLOR } from '../../../ui/palette';

/** What was sampled: histogram bars, the samples' CDF, a measured series. */
export const SAMPLED = SERIES[0];
/** What the model says: the density or CDF the samples should follow, a point it marks. */
export const MODEL = SERIES[1];
/** References drawn over the data (the exact value, a guide to a reading). */
export const REFERENCE = 'var(--muted)';
/** The two Q2 estimators, as the Monte Carlo scene colours them. */
export const UNIFORM = STRATEGY_COLOR.uniform;
export const IMPORTANCE = STRATEGY_COLOR.importance;
/**
 * Bars let what they overlap show through; at this opacity they keep 3 : 1 against the backgrounds
 * (tests/scenes/hemisphere/plotColors.test.ts composites them).
 */
export const BAR_OPACITY = 0.7;
