/**
 * A table of the inversion forms' errors at a few ξ, as the stability panels show it: a focusable
 * scroll box (a wide table scrolls sideways on a phone, also from the keyboard), a row per ξ and a
 * cell per form with its relative error and its error in ulps, marked bad above the tolerance of the
 * arithmetic the table is about.
 */
import type { ReactNode } from 'react';
import { formatNumber } from '../../../ui';

export interface ErrorTableRow {
  key: number;
  /** The row's leading cells (its ξ, and whatever else stands before the forms' errors). */
  lead: ReactNode;
  forms: readonly { id: string | number; relError: number; ulps: number }[];
}

function ErrorCell({ relError, ulps, tolerance }: { relError: number; ulps: number; tolerance: number }) {
  return (
    <td className={relError > tolerance ? 'err-bad' : 'err-ok'}>
      {relError === 0 ? 'exact' : formatNumber(relError, 2)}
      <span className="small">
        {' '}
        {relError === 0 ? '' : `(${ulps < 1e6 ? formatNumber(ulps, 2) : '≫10⁶'} ulp)`}
      </span>
    </td>
  );
}

export function ErrorTable({
  label,
  role,
  testId,
  caption,
  columns,
  rows,
  tolerance,
}: {
  /** The scroll box's accessible name, and its role. */
  label: string;
  role: 'group' | 'region';
  testId?: string;
  /** The table's <caption> element. */
  caption: ReactNode;
  /** The column headers after ξ's. */
  columns: ReactNode;
  rows: readonly ErrorTableRow[];
  /** Relative errors above this are marked bad. */
  tolerance: number;
}) {
  return (
    <div className="table-scroll" tabIndex={0} role={role} aria-label={label}>
      <table className="stability-table" data-testid={testId}>
        {caption}
        <thead>
          <tr>
            <th scope="col">ξ</th>
            {columns}
          </tr>
        </thead>
        <tbody>
          {rows.map((r) => (
            <tr key={r.key}>
              {r.lead}
              {r.forms.map((f) => (
                <ErrorCell key={f.id} relError={f.relError} ulps={f.ulps} tolerance={tolerance} />
              ))}
            </tr>
          ))}
        </tbody>
      </table>
    </div>
  );
}
