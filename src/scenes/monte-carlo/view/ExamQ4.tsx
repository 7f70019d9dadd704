/**
 * Exam Q4, sub-question by sub-question (issue 11): what the exam asks, the written derivation with
 * the steps the key awards marks for (live numbers from the model), the live answer, and where the
 * key's print differs. The numbers follow the page's f, [a, b] and samples; in the exam's
 * configuration they are the exam's.
 */
import type { ReactNode } from 'react';
import { Derivation, ExamPart, formatNumber, KeyNote, LiveAnswer, MathTex, Readout } from '../../../ui';
import { squareAntiderivative, squareNormalizer, type SampleTable } from '../model';
import { formatCount } from '../../../ui/format';

const n4 = (x: number) => (Number.isFinite(x) ? formatNumber(x, 6) : '\\text{—}');
/** v as "p/3" when 3v is (nearly) an integer, else its decimal. */
export function thirds(v: number): string {
  const k = Math.round(v * 3);
  if (Math.abs(v * 3 - k) < 1e-9 * Math.max(1, Math.abs(k)) && k % 3 !== 0) return `\\frac{${k}}{3}`;
  return n4(v);
}
const sq = (c: number) => (c === 0 ? 'x' : `x ${c > 0 ? '+' : '-'} ${n4(Math.abs(c))}`);
const sqAt = (x: number, c: number) => `(${n4(x)} ${c >= 0 ? '+' : '-'} ${n4(Math.abs(c))})^2`;

/** The key's Σ from i = 0 to 4 with the factor 1/4 (Q4 b and c). */
function SumIndexNote({ part }: { part: string }) {
  return (
    <KeyNote testId={`key-sum-${part}`}>
      the key writes <MathTex tex={String.raw`\tfrac14\sum_{i=0}^{4}`} />: that is five terms (i = 0, 1, 2, 3,
      4) divided by 4. The four samples are x₁ … x₄, so the sum runs from i = 1 to 4 (
      <MathTex tex={String.raw`\tfrac14\sum_{i=1}^{4}`} />
      ), as its own arithmetic (four values added) does.
    </KeyNote>
  );
}

/** Terms of a sum for an aligned block, two per row (a long sum would not fit a phone's width). */
function sumRows(terms: string[]): string {
  const rows: string[] = [];
  for (let i = 0; i < terms.length; i += 2) rows.push(terms.slice(i, i + 2).join(' + '));
  return rows.join(String.raw` \\ &\qquad + `);
}

export function Q4a({
  c,
  a,
  b,
  exact,
  isSquare,
}: {
  c: number;
  a: number;
  b: number;
  exact: ReactNode;
  isSquare: boolean;
}) {
  const r = squareAntiderivative(c, a, b);
  const F = (v: { cube: number; lin2: number; lin: number }) =>
    `${n4(v.cube)} + ${n4(v.lin2)} + ${n4(v.lin)}`;
  return (
    <ExamPart
      id="4a"
      title="The integral, analytically"
      asks={<>Evaluate I = ∫₀² (x + 2)² dx analytically.</>}
    >
      <Derivation testId="derivation-4a">
        {!isSquare ? (
          <p className="mc-note">
            Your f is not of the form (x + c)²; this is the exam’s integrand. Your f’s exact integral (by
            quadrature) is the readout below.
          </p>
        ) : null}
        <p>Expand the square, integrate term by term, and evaluate the antiderivative at the limits:</p>
        <div
          className="mc-math"
          tabIndex={0}
          role="group"
          aria-label="derivation (scrolls sideways when wider than the screen)"
        >
          <MathTex
            display
            tex={String.raw`\begin{aligned} I &= \int_{${n4(a)}}^{${n4(b)}} (${sq(c)})^2\,dx \\ &= \int_{${n4(a)}}^{${n4(b)}} \big(x^2 + ${n4(r.twoC)}x + ${n4(r.c2)}\big)\,dx \\ &= \left[\frac{x^3}{3} + ${n4(c)}x^2 + ${n4(r.c2)}x\right]_{${n4(a)}}^{${n4(b)}} \\ &= \big(${F(r.Fb)}\big) - \big(${F(r.Fa)}\big) \\ &= ${n4(r.valueB)} - ${n4(r.valueA)} = ${thirds(r.value)} \approx ${formatNumber(r.value, 10)} \end{aligned}`}
          />
        </div>
      </Derivation>
      <LiveAnswer>{exact}</LiveAnswer>
    </ExamPart>
  );
}

export function Q4b({
  table,
  c,
  a,
  b,
  headline,
  keyFigures,
  children,
}: {
  table: SampleTable;
  c: number | null;
  a: number;
  b: number;
  headline: ReactNode;
  keyFigures: ReactNode;
  children?: ReactNode;
}) {
  const rows = table.rows.filter((r) => !r.outside);
  const N = rows.length;
  const p = 1 / (b - a);
  const sum = rows.reduce((s, r) => s + r.f, 0);
  const est = table.uniform.estimate;
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
      <Derivation testId="derivation-4b">
        <p>
          The pdf is p = 1/(b − a) = {formatNumber(p, 6)}. Evaluate f at each sample, divide by p, and average
          over the N = {N} samples:
        </p>
        <div
          className="mc-math"
          tabIndex={0}
          role="group"
          aria-label="derivation (scrolls sideways when wider than the screen)"
        >
          <MathTex
            display
            tex={String.raw`\begin{aligned} ${rows.map((r, i) => `f(x_${i + 1}) &= ${c === null ? '' : `${sqAt(r.x, c)} = `}${n4(r.f)}`).join(' \\\\ ')} \end{aligned}`}
          />
          <MathTex
            display
            tex={String.raw`\begin{aligned} \langle I\rangle &= \frac{1}{${N}}\sum_{i=1}^{${N}} \frac{f(x_i)}{p(x_i)} \\ &= \frac{1}{${N}\cdot ${n4(p)}}\,\big(${sumRows(rows.map((r) => n4(r.f)))}\big) \\ &= \frac{${n4(sum)}}{${N}\cdot ${n4(p)}} = ${formatNumber(est, 8)} \end{aligned}`}
          />
        </div>
        {children}
      </Derivation>
      <LiveAnswer testId="answer-4b">{headline}</LiveAnswer>
      <SumIndexNote part="4b" />
      {keyFigures}
    </ExamPart>
  );
}

export function Q4c({
  table,
  c,
  a,
  b,
  isSquare,
  answer,
}: {
  table: SampleTable;
  c: number;
  a: number;
  b: number;
  isSquare: boolean;
  answer: ReactNode;
}) {
  const rows = table.rows.filter((r) => !r.outside);
  const N = rows.length;
  const D = squareNormalizer(c, a, b);
  const I = D / 3;
  return (
    <ExamPart
      id="4c"
      title="Importance sampling with p ∝ f"
      asks={
        <>Repeat (b) with importance sampling, using a pdf proportional to the integrand, p(x) ∝ (x + 2)².</>
      }
    >
      <Derivation testId="derivation-4c">
        {isSquare ? (
          <>
            <p>
              Normalise: p must integrate to 1 over [{formatNumber(a, 6)}, {formatNumber(b, 6)}], and ∫ f dx =
              I = {formatNumber(I, 8)} from (a), so
            </p>
            <div className="mc-math" data-testid="pdf-4c" tabIndex={0} role="group" aria-label="the pdf p(x)">
              <MathTex
                display
                tex={String.raw`p(x) = \frac{(${sq(c)})^2}{\int_{${n4(a)}}^{${n4(b)}} (${sq(c)})^2\,dx} = \frac{(${sq(c)})^2}{${thirds(I)}} = \frac{3(${sq(c)})^2}{${n4(D)}}`}
              />
            </div>
            <p>Every term of the estimator is then the same number:</p>
            <div
              className="mc-math"
              tabIndex={0}
              role="group"
              aria-label="derivation (scrolls sideways when wider than the screen)"
            >
              <MathTex
                display
                tex={String.raw`\frac{f(x_i)}{p(x_i)} = \frac{(x_i ${c >= 0 ? '+' : '-'} ${n4(Math.abs(c))})^2}{\tfrac{3}{${n4(D)}}(x_i ${c >= 0 ? '+' : '-'} ${n4(Math.abs(c))})^2} = \frac{${n4(D)}}{3} \approx ${n4(I)}`}
              />
              <MathTex
                display
                tex={String.raw`\begin{aligned} ${rows.map((r, i) => `\\frac{f(x_${i + 1})}{p(x_${i + 1})} &= ${formatNumber(r.propRatio, 12)}`).join(' \\\\ ')} \end{aligned}`}
              />
              <MathTex
                display
                tex={String.raw`{\langle I\rangle = \frac{1}{${N}}\sum_{i=1}^{${N}} \frac{f(x_i)}{p(x_i)} = ${thirds(table.proportional?.estimate ?? NaN)}},\allowbreak\qquad {s^2 = 0}`}
              />
            </div>
          </>
        ) : (
          <p>
            For your f the pdf is p = |f| / ∫|f| dx (tabulated); every term f/p is then ∫ f dx up to the
            table’s resolution.
          </p>
        )}
        <p>
          Zero variance: whatever samples are drawn, each term equals I, so one sample already gives the exact
          answer. (Building this p needed I itself: in rendering, p ∝ f is the ideal that BSDF and light
          sampling approximate.)
        </p>
      </Derivation>
      <LiveAnswer testId="answer-4c">{answer}</LiveAnswer>
      <SumIndexNote part="4c" />
    </ExamPart>
  );
}

export function Q4d({
  uErr,
  iErr,
  N,
  onWhole,
  importanceIsExam,
}: {
  uErr: number;
  iErr: number;
  N: number;
  onWhole: () => void;
  importanceIsExam: boolean;
}) {
  return (
    <ExamPart
      id="4d"
      title="Convergence"
      asks={
        <>
          Draw a convergence graph: the Monte Carlo estimate as the number of samples grows, for (b) and (c).
          Which converges faster?
        </>
      }
    >
      <Derivation title="The graph">
        <p>
          The animation at the top of this question is the graph: the running estimate ⟨I⟩ against N for
          uniform sampling (b) and importance sampling (c), drawn from the same random numbers, with the ±
          s/√N band and |error| on log-log axes. Uniform sampling wanders around I and closes in like σ/√N
          (the |error| curve follows the N^−½ trend);
          {importanceIsExam
            ? ' importance sampling with p ∝ f sits on I from the first sample.'
            : ' the importance lane uses your chosen pdf.'}
        </p>
        <button type="button" onClick={onWhole} data-testid="race-whole">
          Show the whole run ({formatCount(N)} samples)
        </button>
      </Derivation>
      <LiveAnswer>
        <div className="readouts">
          <Readout
            id="q4d-uniform-error"
            label={`uniform |error| after N = ${formatCount(N)}`}
            value={uErr}
            digits={3}
          />
          <Readout
            id="q4d-importance-error"
            label={`importance |error| after N = ${formatCount(N)}`}
            value={iErr}
            digits={3}
          />
        </div>
        {importanceIsExam ? (
          <p data-testid="answer-4d">
            <strong>(c) converges faster</strong>: it has zero variance (every term f/p equals I), so its
            error is at rounding level for every N, while the uniform estimator’s error only falls like N^−½.
          </p>
        ) : (
          <p data-testid="answer-4d">
            With p ∝ f (the exam’s (c)) the importance estimate would be exact at every N (zero variance);
            your pdf only approximates f, so its error also falls like N^−½, with a smaller constant when p
            follows f more closely.
          </p>
        )}
      </LiveAnswer>
    </ExamPart>
  );
}
