/**
 * The stability comparison of the inversion formulas, behind a disclosure: its panel (and the
 * high-precision arithmetic it needs) loads only when opened.
 */
import { lazy, Suspense, useState } from 'react';

const StabilityPanel = lazy(() => import('./StabilityPanel').then((m) => ({ default: m.StabilityPanel })));

export function StabilityDetails() {
  const [open, setOpen] = useState(false);
  return (
    <details onToggle={(e) => setOpen(e.currentTarget.open)} data-testid="stability-details">
      <summary>Compare ½ arccos(1 − 2ξ) with arcsin √ξ, and ln with log1p, at tiny and near-1 ξ</summary>
      {open ? (
        <Suspense fallback={<p>Loading…</p>}>
          <StabilityPanel />
        </Suspense>
      ) : null}
    </details>
  );
}
