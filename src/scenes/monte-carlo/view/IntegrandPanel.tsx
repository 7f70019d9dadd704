/**
 * The integrand and the chosen pdf drawn over [a, b] with the samples of the worked table, and the
 * estimator's formulas.
 */
import { useMemo } from 'react';
import { MathTex, Panel } from '../../../ui';
import { curves } from '../curves';
import type { Fn1 } from '../integral';
import type { PdfChoice } from '../pdfChoice';
import type { SampleTable } from '../sampleTable';
import { MathBlock } from './examMath';
import { FunctionPlot } from './FunctionPlot';

/** The problem as drawn: the pdf chosen, f (null while it compiles) over [a, b], the worked table's samples. */
export interface IntegrandProps {
  choice: PdfChoice | null;
  f: Fn1 | null;
  table: SampleTable | null;
  a: number;
  b: number;
}

export function IntegrandPanel({ choice, f, table, a, b }: IntegrandProps) {
  // f and the pdf sampled over [a, b], computed here so that a closed fold costs nothing
  const curve = useMemo(
    () => (f ? curves(f, choice && choice.ok ? choice.density : null, a, b) : null),
    [f, choice, a, b],
  );
  return (
    <Panel title="The integrand and the pdf">
      {choice && choice.ok ? (
        <p className="mc-pdf-label">
          {choice.label}
          {choice.note ? <span className="mc-note"> {choice.note}</span> : null}
        </p>
      ) : null}
      {curve ? (
        <FunctionPlot
          curve={curve}
          samples={table ? table.rows.map((r): [number, number] => [r.x, r.f]) : []}
          a={a}
          b={b}
        />
      ) : null}
      <MathBlock label="formulas (scroll sideways when wider than the screen)">
        <MathTex
          display
          tex={String.raw`\begin{gathered}\langle I\rangle = \frac{1}{N}\sum_{i=1}^{N}\frac{f(x_i)}{p(x_i)},\quad x_i\sim p \\ \operatorname{SE} = \frac{s}{\sqrt N}\ \text{(independent } x_i \text{ only)} \\ s^2 = \frac{1}{N-1}\sum_{i=1}^{N}\Big(\frac{f(x_i)}{p(x_i)} - \langle I\rangle\Big)^2\end{gathered}`}
        />
      </MathBlock>
    </Panel>
  );
}
