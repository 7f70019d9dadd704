/**
 * The worked Q4 table: xᵢ, f(xᵢ), p(xᵢ), f/p and the estimates, computed live, with the places where
 * the answer key's printed figures differ from the computation.
 */
import { formatNumber, Notice, Readout } from '../../../ui';
import type { KeyNote } from '../exam';
import type { SampleTable } from '../sampleTable';
import type { PdfKind } from '../params';

const num = (x: number, d = 6) => (Number.isFinite(x) ? formatNumber(x, d) : '—');

export function SampleRows({
  table,
  pdfOk,
  pdfKind,
}: {
  table: SampleTable;
  pdfOk: boolean;
  pdfKind: PdfKind;
}) {
  return (
    <div
      className="mc-table-wrap"
      tabIndex={0}
      role="group"
      aria-label="The samples (the table scrolls sideways on narrow screens)"
    >
      <table className="mc-table">
        <caption className="sr-only">Samples, integrand, pdf and their ratio</caption>
        <thead>
          <tr>
            <th scope="col">i</th>
            <th scope="col">xᵢ</th>
            <th scope="col">f(xᵢ)</th>
            <th scope="col">p(xᵢ) ({pdfKind === 'proportional' ? 'p ∝ f' : pdfKind})</th>
            <th scope="col">f/p</th>
          </tr>
        </thead>
        <tbody>
          {table.rows.map((r, i) => (
            <tr key={i} className={r.outside ? 'mc-outside' : undefined}>
              <td>{i + 1}</td>
              <td className="mono">{num(r.x, 8)}</td>
              <td>
                <Readout
                  id={`f-${i}`}
                  label={<span className="sr-only">f(x{i + 1})</span>}
                  value={r.f}
                  digits={8}
                />
              </td>
              <td>
                <Readout
                  id={`p-${i}`}
                  label={<span className="sr-only">p(x{i + 1})</span>}
                  value={pdfOk ? r.p : null}
                  digits={8}
                />
              </td>
              <td className="mono">{pdfOk ? num(r.ratio, 8) : '—'}</td>
            </tr>
          ))}
        </tbody>
      </table>
      {table.problems.map((p, i) => (
        <Notice key={i} kind="warn">
          {p.message}
        </Notice>
      ))}
    </div>
  );
}

/** Where the key's printed Q4(b) figures differ from the computation (exam configuration only). */
export function KeyFigures({ keyNotes, a, b }: { keyNotes: KeyNote[]; a: number; b: number }) {
  if (!keyNotes.length) return null;
  const differing = keyNotes.filter((k) => !k.agrees);
  const printedSum = keyNotes.slice(0, 4).reduce((s, k) => s + k.printed, 0);
  return (
    <div className="mc-key" data-testid="key-notes">
      {differing.length ? (
        <Notice kind="info">
          <p>
            <strong>Where the answer key’s printed figures differ.</strong> The key prints intermediate values
            that do not match the computation (the final figure does):
          </p>
          <ul>
            {keyNotes.map((k, i) => (
              <li key={i}>
                {k.what}: computed <span className="mono">{formatNumber(k.computed, 8)}</span> (≈{' '}
                {k.rounded.toFixed(2)}); key prints <span className="mono">{k.printed.toFixed(2)}</span> —{' '}
                {k.agrees
                  ? 'agrees'
                  : Math.abs(k.computed - k.printed) < 0.0101
                    ? 'the key truncated instead of rounding'
                    : 'a slip in the key'}
              </li>
            ))}
          </ul>
          <p>
            The key’s four printed values sum to {formatNumber(printedSum, 6)}, which would give{' '}
            {formatNumber((printedSum / 4) * (b - a), 6)}, not its printed {keyNotes[4]?.printed.toFixed(2)};
            its final answer matches the computed {formatNumber(keyNotes[4]?.computed ?? NaN, 6)}, so the
            intermediates are typos.
          </p>
        </Notice>
      ) : (
        <p className="mc-note">Every figure the key prints for Q4(b) agrees with the computation.</p>
      )}
    </div>
  );
}
