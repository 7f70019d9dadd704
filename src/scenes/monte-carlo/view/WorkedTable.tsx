/**
 * The worked Q4 table: xᵢ, f(xᵢ), p(xᵢ), f/p and the estimates, computed live, with the places where
 * the answer key's printed figures differ from the computation.
 */
import { formatNumber, MathTex, Notice, Panel, Readout } from '../../../ui';
import type { KeyNote, SampleTable } from '../model';
import type { PdfKind } from '../params';

const num = (x: number, d = 6) => (Number.isFinite(x) ? formatNumber(x, d) : '—');

export function WorkedTable(props: {
  table: SampleTable;
  keyNotes: KeyNote[];
  given: boolean;
  pdfOk: boolean;
  pdfKind: PdfKind;
  a: number;
  b: number;
  onUseExam: () => void;
  onDraw: () => void;
}) {
  const { table, keyNotes, given, pdfOk, pdfKind } = props;
  const differing = keyNotes.filter((k) => !k.agrees);
  return (
    <Panel title={given ? 'Worked estimate with the given samples (Q4 b, c)' : 'Worked Q4 (b, c): the exam’s four samples'}>
      <div className="mc-table-wrap">
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
                  <Readout id={`f-${i}`} label={<span className="sr-only">f(x{i + 1})</span>} value={r.f} digits={8} />
                </td>
                <td>
                  <Readout id={`p-${i}`} label={<span className="sr-only">p(x{i + 1})</span>} value={pdfOk ? r.p : null} digits={8} />
                </td>
                <td className="mono">{pdfOk ? num(r.ratio, 8) : '—'}</td>
              </tr>
            ))}
          </tbody>
        </table>
      </div>
      <div className="readouts mc-q4-readouts">
        <Readout id="q4-uniform" label="uniform ⟨I⟩ = (b − a)/N Σ f(xᵢ)" value={table.uniform.invalid ? null : table.uniform.estimate} digits={10} />
        <Readout
          id="q4-importance"
          label="importance ⟨I⟩ with p ∝ f"
          value={table.proportional && !table.proportional.invalid ? table.proportional.estimate : null}
          digits={10}
          note={table.proportional && table.proportional.n > 1 ? `spread of f/p: s = ${formatNumber(Math.sqrt(table.proportional.variance), 3)} (zero variance)` : undefined}
        />
      </div>
      <div className="mc-math">
        <MathTex
          display
          tex={String.raw`\begin{gathered}\langle I\rangle_{\text{uniform}} = \frac{b-a}{N}\sum_i f(x_i) \\ p = \frac{f}{\int_a^b f\,dx} \\ \Rightarrow\; \frac{f(x_i)}{p(x_i)} = \int_a^b f\,dx \text{ for every } x_i\end{gathered}`}
        />
      </div>
      {table.problems.map((p, i) => (
        <Notice key={i} kind="warn">
          {p}
        </Notice>
      ))}
      {keyNotes.length ? (
        <div className="mc-key" data-testid="key-notes">
          {differing.length ? (
            <Notice kind="info">
              <p>
                <strong>Where the answer key’s printed figures differ.</strong> The key prints intermediate values that do not match the computation (the final
                figure does):
              </p>
              <ul>
                {keyNotes.map((k, i) => (
                  <li key={i}>
                    {k.what}: computed <span className="mono">{formatNumber(k.computed, 8)}</span> (≈ {k.rounded.toFixed(2)}); key prints{' '}
                    <span className="mono">{k.printed.toFixed(2)}</span> — {k.agrees ? 'agrees' : Math.abs(k.computed - k.printed) < 0.0101 ? 'the key truncated instead of rounding' : 'a slip in the key'}
                  </li>
                ))}
              </ul>
              <p>
                The key’s four printed values sum to {formatNumber(keyNotes.slice(0, 4).reduce((s, k) => s + k.printed, 0), 6)}, which would give{' '}
                {formatNumber((keyNotes.slice(0, 4).reduce((s, k) => s + k.printed, 0) / 4) * (props.b - props.a), 6)}, not its printed {keyNotes[4]?.printed.toFixed(2)}; its final answer
                matches the computed {formatNumber(keyNotes[4]?.computed ?? NaN, 6)}, so the intermediates are typos.
              </p>
            </Notice>
          ) : (
            <p className="mc-note">Every figure the key prints for Q4(b) agrees with the computation.</p>
          )}
        </div>
      ) : null}
      <div className="mc-buttons">
        {given ? (
          <button type="button" onClick={props.onDraw}>
            Draw N samples instead
          </button>
        ) : (
          <button type="button" onClick={props.onUseExam}>
            Use these four samples for the estimate
          </button>
        )}
      </div>
    </Panel>
  );
}
