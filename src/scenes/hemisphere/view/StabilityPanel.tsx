/**
 * The numerical-stability panel: the θ and φ inversion forms evaluated at tiny and near-1 ξ, with
 * their errors against a 64-digit reference (decimal.js, loaded only when the panel is opened —
 * core/sampling/stability).
 */
import { useEffect, useState } from 'react';
import { MathTex, Notice, formatNumber, keepTextParenthesesTogether } from '../../../ui';
import {
  STABILITY_FORMS,
  STABILITY_XIS,
  computeStabilityReference,
  stabilityTable,
  type StabilityRow,
} from '../../../core/sampling';
import { ErrorTable } from './ErrorTable';

function xiLabel(xi: number): string {
  if (xi === 2 ** -53) return '2⁻⁵³';
  if (xi === 1 - 2 ** -53) return '1 − 2⁻⁵³';
  if (xi > 0.5 && xi < 1) return `1 − ${formatNumber(1 - xi, 2)}`;
  return formatNumber(xi, 3);
}

// plain-text formulas: the line wraps outside their parentheses, never inside
const WHY_STABLE_FORMS = keepTextParenthesesTogether(
  '½ arccos(1 − 2ξ) returns exactly 0 once ξ < 2⁻⁵⁴ (1 − 2ξ rounds to 1) and keeps only half the ' +
    'digits above that; arcsin √ξ is accurate there but near ξ = 1 amplifies the rounding of √ξ (arcsin is ' +
    'ill-conditioned at 1). ln(cξ + 1) loses the small cξ to the +1. The sampler uses sin θ = √ξ₁, ' +
    'cos θ = √(1 − ξ₁) and log1p(expm1(2π) ξ₂), all within an ulp or two everywhere.',
);

export function StabilityPanel() {
  const [rows, setRows] = useState<StabilityRow[] | null>(null);
  const [error, setError] = useState<string | null>(null);
  useEffect(() => {
    let alive = true;
    computeStabilityReference(STABILITY_XIS).then(
      (ref) => alive && setRows(stabilityTable(ref)),
      (e: unknown) => alive && setError(e instanceof Error ? e.message : String(e)),
    );
    return () => {
      alive = false;
    };
  }, []);
  if (error)
    return <Notice kind="error">The high-precision reference could not be computed ({error}).</Notice>;
  if (!rows) return <p role="status">Computing the 64-digit reference…</p>;
  return (
    <div className="stability" data-testid="stability">
      {(['theta', 'phi'] as const).map((q) => {
        const forms = STABILITY_FORMS.filter((f) => f.quantity === q);
        return (
          <ErrorTable
            key={q}
            label={q === 'theta' ? 'errors of the θ forms' : 'errors of the φ forms'}
            role="region"
            caption={
              <caption>
                {q === 'theta'
                  ? 'θ(ξ₁): relative error (and ulps) against the 64-digit reference'
                  : 'φ(ξ₂): relative error (and ulps)'}
              </caption>
            }
            columns={
              <>
                <th scope="col">reference</th>
                {forms.map((f) => (
                  <th scope="col" key={f.id}>
                    <MathTex tex={f.tex} />
                  </th>
                ))}
              </>
            }
            rows={rows
              .filter((r) => r.quantity === q)
              .map((r) => ({
                key: r.xi,
                lead: (
                  <>
                    <th scope="row">{xiLabel(r.xi)}</th>
                    <td className="mono">
                      {r.reference !== 0 && Math.abs(r.reference) < 1e-3
                        ? r.reference.toExponential(9)
                        : r.reference.toPrecision(10)}
                    </td>
                  </>
                ),
                forms: r.forms,
              }))}
            tolerance={1e-12}
          />
        );
      })}
      <p className="small">{WHY_STABLE_FORMS}</p>
    </div>
  );
}
