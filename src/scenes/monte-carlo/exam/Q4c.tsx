/**
 * Exam Q4(c): importance sampling with p ∝ f. For a square f = (x + c)² the derivation is written
 * out with the page's numbers; for another f the pdf is the tabulated |f| / ∫|f| dx.
 */
import { ExamPart, formatNumber, keepTextParenthesesTogether, MathTex, Readout } from '../../../ui';
import { estimateHasZeroVariance } from '../zeroVariance';
import { squareNormalizer } from '../exam';
import type { SampleTable } from '../sampleTable';
import { MathBlock, n4, shifted, thirds, WorkedAnswer } from '../view/examMath';

export function Q4c({
  table,
  c,
  a,
  b,
  isSquare,
  ask,
}: {
  table: SampleTable;
  c: number;
  a: number;
  b: number;
  isSquare: boolean;
  /** ask=1, not yet revealed: the derivation and the answer are hidden. */
  ask: boolean;
}) {
  const rows = table.rows.filter((r) => !r.outside);
  const N = rows.length;
  const D = squareNormalizer(c, a, b);
  const I = D / 3;
  const sign = c >= 0 ? '+' : '-';
  const prop = table.proportional;
  const headline = (
    <Readout
      id="q4-importance"
      label="importance ⟨I⟩ with p ∝ f"
      value={prop && !prop.invalid ? prop.estimate : null}
      digits={10}
      note={
        prop && prop.n > 1
          ? estimateHasZeroVariance(prop)
            ? `spread of f/p: s = ${formatNumber(Math.sqrt(prop.variance), 3)}, zero to rounding (zero variance)`
            : `spread of f/p: s = ${formatNumber(Math.sqrt(prop.variance), 3)}`
          : undefined
      }
    />
  );
  return (
    <ExamPart
      id="4c"
      title="Importance sampling with p ∝ f"
      asks={
        <>
          Repeat (b) with importance sampling, using a pdf proportional to the integrand, p(x) ∝{' '}
          {keepTextParenthesesTogether('(x + 2)²')}.
        </>
      }
    >
      <WorkedAnswer
        part="4c"
        ask={ask}
        headline={headline}
        answer={
          <p>
            Zero variance: whatever samples are drawn, each term equals I, so one sample already gives the
            exact answer. (Building this p needed I itself: in rendering, p ∝ f is the ideal that BSDF and
            light sampling approximate.)
          </p>
        }
      >
        {isSquare ? (
          <>
            <p>
              Normalise: p must integrate to 1 over [{formatNumber(a, 6)}, {formatNumber(b, 6)}], and ∫ f dx =
              I = {formatNumber(I, 8)} from (a), so
            </p>
            <MathBlock testId="pdf-4c" label="the pdf p(x)">
              <MathTex
                display
                tex={String.raw`p(x) = \frac{(${shifted(c)})^2}{\int_{${n4(a)}}^{${n4(b)}} (${shifted(c)})^2\,dx} = \frac{(${shifted(c)})^2}{${thirds(I)}} = \frac{3(${shifted(c)})^2}{${n4(D)}}`}
              />
            </MathBlock>
            <p>Every term of the estimator is then the same number:</p>
            <MathBlock>
              <MathTex
                display
                tex={String.raw`\frac{f(x_i)}{p(x_i)} = \frac{(x_i ${sign} ${n4(Math.abs(c))})^2}{\tfrac{3}{${n4(D)}}(x_i ${sign} ${n4(Math.abs(c))})^2} = \frac{${n4(D)}}{3} \approx ${n4(I)}`}
              />
              {/* one formula per term, wrapping two to a line where there is room */}
              <div className="mc-terms">
                {rows.map((r, k) => (
                  <MathTex
                    key={k}
                    tex={String.raw`\dfrac{f(x_${k + 1})}{p(x_${k + 1})} = ${formatNumber(r.propRatio, 12)}`}
                  />
                ))}
              </div>
              <MathTex
                display
                tex={String.raw`{\langle I\rangle = \frac{1}{${N}}\sum_{i=1}^{${N}} \frac{f(x_i)}{p(x_i)} = ${thirds(prop?.estimate ?? NaN)}},\allowbreak\qquad {s^2 = 0}`}
              />
            </MathBlock>
          </>
        ) : (
          <p>
            For your f the pdf is p = |f| / ∫|f| dx (tabulated); every term f/p is then ∫ f dx up to the
            table’s resolution.
          </p>
        )}
      </WorkedAnswer>
    </ExamPart>
  );
}
