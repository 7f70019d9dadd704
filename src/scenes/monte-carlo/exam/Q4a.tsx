/**
 * Exam Q4(a): the integral, analytically. The numbers follow the page's f and [a, b] when f is a
 * square (x + c)²; otherwise the exam's integrand is derived and the page's f has its readout.
 */
import {
  Derivation,
  ExamPart,
  Revealed,
  formatNumber,
  keepTextParenthesesTogether,
  LiveAnswer,
  MathTex,
  Readout,
} from '../../../ui';
import { squareAntiderivative } from '../exam';
import type { Exact } from '../integral';
import { MathBlock, n4, shifted, thirds, Worked } from '../view/examMath';

export function Q4a({
  c,
  a,
  b,
  exact,
  isSquare,
  ask,
}: {
  c: number;
  a: number;
  b: number;
  /** The page's f's exact integral (null while f compiles). */
  exact: Exact | null;
  isSquare: boolean;
  /** ask=1, not yet revealed: the derivation and the answer are hidden. */
  ask: boolean;
}) {
  const r = squareAntiderivative(c, a, b);
  const F = (v: { cube: number; lin2: number; lin: number }) =>
    `${n4(v.cube)} + ${n4(v.lin2)} + ${n4(v.lin)}`;
  return (
    <ExamPart
      id="4a"
      title="The integral, analytically"
      asks={<>Evaluate I = ∫₀² {keepTextParenthesesTogether('(x + 2)²')} dx analytically.</>}
    >
      <Revealed ask={ask} what="the derivation and the answer">
        <Worked>
          <Derivation testId="derivation-4a">
            {!isSquare ? (
              <p className="mc-note">
                Your f is not of the form {keepTextParenthesesTogether('(x + c)²')}; this is the exam’s
                integrand. Your f’s exact integral (by quadrature) is the readout below.
              </p>
            ) : null}
            <p>Expand the square, integrate term by term, and evaluate the antiderivative at the limits:</p>
            <MathBlock>
              <MathTex
                display
                tex={String.raw`\begin{aligned} I &= \int_{${n4(a)}}^{${n4(b)}} (${shifted(c)})^2\,dx \\ &= \int_{${n4(a)}}^{${n4(b)}} \big(x^2 + ${n4(r.twoC)}x + ${n4(r.c2)}\big)\,dx \\ &= \left[\frac{x^3}{3} + ${n4(c)}x^2 + ${n4(r.c2)}x\right]_{${n4(a)}}^{${n4(b)}} \\ &= \big(${F(r.Fb)}\big) - \big(${F(r.Fa)}\big) \\ &= ${n4(r.valueB)} - ${n4(r.valueA)} = ${thirds(r.value)} \approx ${formatNumber(r.value, 10)} \end{aligned}`}
              />
            </MathBlock>
          </Derivation>
          <LiveAnswer>
            <Readout
              id="exact"
              label="exact ∫ f dx"
              value={exact?.value ?? null}
              digits={12}
              note={exact ? (exact.problem ?? exact.method) : 'compiling f…'}
            />
          </LiveAnswer>
        </Worked>
      </Revealed>
    </ExamPart>
  );
}
