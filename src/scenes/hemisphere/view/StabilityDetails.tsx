/**
 * The stability comparison of the inversion formulas, folded: its panel (and the high-precision
 * arithmetic it needs) loads only when opened.
 */
import { lazy } from 'react';
import { Fold } from '../../../ui/Fold';
import { keepTextParenthesesTogether } from '../../../ui';

const StabilityPanel = lazy(() => import('./StabilityPanel').then((m) => ({ default: m.StabilityPanel })));

export function StabilityDetails() {
  return (
    <Fold
      name="stability"
      testId="stability-details"
      summary={keepTextParenthesesTogether(
        'Numerical stability: ½ arccos(1 − 2ξ) against arcsin √ξ, and ln against log1p, at tiny and near-1 ξ',
      )}
    >
      <StabilityPanel />
    </Fold>
  );
}
