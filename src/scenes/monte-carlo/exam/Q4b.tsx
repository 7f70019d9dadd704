/**
 * Exam Q4(b): uniform sampling with the four given samples. The derivation and the worked table use
 * the page's samples (the exam's four unless others are given); the page's own estimate (drawn or
 * given samples, the chosen pdf and sequence) follows as `estimate`.
 */
import type { ReactNode } from 'react';
import { ExamPart, formatNumber, keepTextParenthesesTogether, MathTex, Readout } from '../../../ui';
import { formatCount } from '../../../ui/format';
import { EXAM_SAMPLES, roundTo, type KeyNote } from '../exam';
import type { SampleTable } from '../sampleTable';
import type { PdfKind, Strategy } from '../params';
import { MathBlock, n4, squareAt, sumRows, WorkedAnswer } from '../view/examMath';
import { KeyFigures, SampleRows } from '../view/WorkedTable';

export function Q4b({
  table,
  c,
  a,
  b,
  given,
  pdfOk,
  pdfKind,
  seq,
  n,
  keyNotes,
  onSamples,
  estimate,
  ask,
}: {
  table: SampleTable;
  /** The shift of f = (x + c)², or null when f is no such square. */
  c: number | null;
  a: number;
  b: number;
  /** Whether the estimate uses the given samples (else N drawn ones). */
  given: boolean;
  pdfOk: boolean;
  pdfKind: PdfKind;
  seq: Strategy;
  n: number;
  keyNotes: KeyNote[];
  onSamples: (samples: number[] | null) => void;
  estimate: ReactNode;
  /** ask=1, not yet revealed: the derivation and the answer are hidden. */
  ask: boolean;
}) {
  const rows = table.rows.filter((r) => !r.outside);
  const N = rows.length;
  const p = 1 / (b - a);
  const sum = rows.reduce((s, r) => s + r.f, 0);
  const est = table.uniform.estimate;
  const headline = (
    <Readout
      id="q4-uniform"
      label="uniform ⟨I⟩ = (b − a)/N Σ f(xᵢ)"
      value={table.uniform.invalid ? null : table.uniform.estimate}
      digits={6}
      note={
        table.uniform.invalid
          ? undefined
          : `to 2 decimals, as the exam writes it: ${roundTo(table.uniform.estimate, 2).toFixed(2)}`
      }
    />
  );
  const answer = (
    <>
      <SampleRows table={table} pdfOk={pdfOk} pdfKind={pdfKind} />
      <div className="mc-buttons">
        {given ? (
          <button type="button" onClick={() => onSamples(null)}>
            Draw N samples instead
          </button>
        ) : (
          <button type="button" onClick={() => onSamples([...EXAM_SAMPLES])}>
            Use these four samples for the estimate
          </button>
        )}
      </div>
      <h5 className="mc-subhead">
        With the page’s settings ({given ? 'the given samples' : `N = ${formatCount(n)} drawn samples`}, pdf{' '}
        {pdfKind}, {seq})
      </h5>
      {estimate}
    </>
  );
  return (
    <ExamPart
      id="4b"
      title="Uniform sampling with the four given samples"
      asks={
        <>
          Estimate I by Monte Carlo with the uniform pdf p(x) = 1/2 on [0, 2] and the samples x = 1.16, 1.98,
          0.54, 1.26.
        </>
      }
    >
      <WorkedAnswer
        part="4b"
        ask={ask}
        headline={headline}
        answer={answer}
        after={<KeyFigures keyNotes={keyNotes} a={a} b={b} />}
      >
        <p>
          The pdf is p = {keepTextParenthesesTogether('1/(b − a)')} = {formatNumber(p, 6)}. Evaluate f at each
          sample, divide by p, and average over the N = {N} samples:
        </p>
        <MathBlock>
          <MathTex
            display
            tex={String.raw`\begin{aligned} ${rows.map((r, i) => `f(x_${i + 1}) &= ${c === null ? '' : `${squareAt(r.x, c)} = `}${n4(r.f)}`).join(' \\\\ ')} \end{aligned}`}
          />
          <MathTex
            display
            tex={String.raw`\begin{aligned} \langle I\rangle &= \frac{1}{${N}}\sum_{i=1}^{${N}} \frac{f(x_i)}{p(x_i)} \\ &= \frac{1}{${N}\cdot ${n4(p)}}\,\big(${sumRows(rows.map((r) => n4(r.f)))}\big) \\ &= \frac{${n4(sum)}}{${N}\cdot ${n4(p)}} = ${formatNumber(est, 8)} \end{aligned}`}
          />
        </MathBlock>
      </WorkedAnswer>
    </ExamPart>
  );
}
