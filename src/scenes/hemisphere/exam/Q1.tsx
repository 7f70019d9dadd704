/**
 * Exam Q1, part by part: what the exam asks, the written derivation with the steps the
 * key awards marks for (every number computed live by the model), then the live answer. The
 * derivation is always the exam's lobe k cos θ e^φ; another lobe's derivation is in "Explore further".
 */
import type { ReactNode } from 'react';
import { ExamPart, Derivation as DerivationBlock, KeyNote } from '../../../ui/exam';
import { Answer } from '../view/Answer';
import { MathTex, Readout, formatNumber } from '../../../ui';
import { examInversion, type ExamChecks } from '../examChecks';
import { texNum } from '../view/tex';
import { Steps } from '../view/Steps';

const M = ({ t }: { t: string }) => <MathTex tex={t} />;

export interface Q1Props {
  c: ExamChecks;
  /** The first sample's (ξ₁, ξ₂) of the current point set: the worked example of (c) and (d). */
  xi: { xi1: number; xi2: number } | null;
  /** True when the page shows the divergence panel for the paper's identity (jacobian=inverted). */
  invertedShown: boolean;
  onShowInverted: () => void;
  /** Live answers, supplied by the scene (the sample check, the divergence panel). */
  inverted: ReactNode;
  answer1d: ReactNode;
  /** The CDFs plotted (the chosen density's, against the samples), under (c)'s answer. */
  cdfs: ReactNode;
  /** A note when the sampled lobe is not the exam's. */
  otherLobe: ReactNode;
  /** `data-testid="derivation"` goes on part (a) when the exam lobe is chosen (the contract's test hook). */
  mainTestId: boolean;
  /** Results hidden until revealed (`ask=1`): the live answers wait, the derivations stay. */
  ask: boolean;
}

export function Q1({
  c,
  xi,
  invertedShown,
  onShowInverted,
  inverted,
  answer1d,
  cdfs,
  otherLobe,
  mainTestId,
  ask,
}: Q1Props) {
  const k = texNum(c.k, 8);
  const E = texNum(c.e2piMinus1, 8);
  const ex = xi ? examInversion(xi.xi1, xi.xi2) : null;
  return (
    <>
      <ExamPart
        id="1a"
        title="Normalize p(ω)"
        asks={
          <>
            Find k so that p(ω) = k cos θ e<sup>φ</sup> is a probability density over the upper hemisphere.
          </>
        }
      >
        <DerivationBlock testId={mainTestId ? 'derivation' : 'derivation-1a'}>
          <p>
            Normalize over solid angle: a density over directions integrates to 1 over the hemisphere Ω, and
            dω = sin θ dθ dφ.
          </p>
          <Steps
            label="Normalize over solid angle (Q1a)"
            testId="steps-1a"
            lines={[
              {
                tex: `\\int_\\Omega p(\\omega)\\,d\\omega = \\int_0^{\\pi/2}\\!\\!\\int_0^{2\\pi} k\\cos\\theta\\,e^{\\phi}\\,\\sin\\theta\\,d\\phi\\,d\\theta = 1`,
                why: (
                  <>
                    dω = sin θ dθ dφ: sin θ is the radius of the ring of directions at polar angle θ, so a
                    patch dθ × dφ has area sin θ dθ dφ
                  </>
                ),
              },
              {
                tex: `k\\int_0^{\\pi/2}\\cos\\theta\\sin\\theta\\,d\\theta\\;\\int_0^{2\\pi}e^{\\phi}\\,d\\phi = 1`,
                why: 'the integrand is a product of a θ-part and a φ-part, so the double integral splits',
              },
              {
                tex: `k\\cdot\\tfrac12\\int_0^{\\pi/2}\\sin 2\\theta\\,d\\theta\\;\\int_0^{2\\pi}e^{\\phi}\\,d\\phi = 1`,
                why: <>identity: sin 2θ = 2 sin θ cos θ, so sin θ cos θ = ½ sin 2θ</>,
              },
              {
                tex: `k\\cdot\\tfrac12\\Big[-\\tfrac12\\cos 2\\theta\\Big]_0^{\\pi/2}\\int_0^{2\\pi}e^{\\phi}\\,d\\phi = 1`,
                why: 'integrate: an antiderivative of sin 2θ is −½ cos 2θ',
              },
              {
                tex: `\\Big[-\\tfrac12\\cos 2\\theta\\Big]_0^{\\pi/2} = -\\tfrac12(\\cos\\pi-\\cos 0) = -\\tfrac12(-1-1) = ${texNum(c.bracket, 10)}`,
                why: (
                  <>
                    evaluate at the limits (computed: the θ-integral ½ · this = {texNumPlain(c.thetaIntegral)}{' '}
                    by quadrature)
                  </>
                ),
              },
              {
                tex: `k\\cdot\\tfrac12\\,\\Big[e^{\\phi}\\Big]_0^{2\\pi} = k\\cdot\\tfrac12\\,(e^{2\\pi}-e^{0}) = k\\cdot\\tfrac12\\,(e^{2\\pi}-1) = 1`,
                why: (
                  <>
                    the φ-integral: e<sup>2π</sup> − 1 = {texNumPlain(c.phiIntegral, 10)} (quadrature)
                  </>
                ),
              },
              {
                tex: `k = \\frac{2}{e^{2\\pi}-1} = \\frac{2}{${E}} = ${k}`,
                why: (
                  <>
                    computed as 2/expm1(2π); check: ∫ p dω with this k = {texNumPlain(c.total, 12)}{' '}
                    (quadrature)
                  </>
                ),
              },
            ]}
          />
        </DerivationBlock>
        <Answer testId="answer-1a" ask={ask} what="k">
          <div className="readouts">
            <Readout id="k" label="k (normalization of p(ω))" value={c.k} digits={8} note="= 2/expm1(2π)" />
          </div>
        </Answer>
      </ExamPart>

      <ExamPart
        id="1b"
        title="Marginal densities"
        asks={
          <>
            Change variables to p(θ, φ) with the identity the paper gives, then find the marginal densities
            p(θ) and p(φ). The paper prints the identity as{' '}
            <M t={`p(\\omega) = \\sin\\theta\\,p(\\theta,\\phi)`} />.
          </>
        }
      >
        <DerivationBlock testId="derivation-1b">
          <p>
            Probability is conserved under the change of variables: p(θ, φ) dθ dφ = p(ω) dω, and dω = sin θ dθ
            dφ, so the correct identity is <M t={`p(\\theta,\\phi) = \\sin\\theta\\,p(\\omega)`} />.
          </p>
          <Steps
            label="Marginal of θ (Q1b)"
            testId="steps-1b-theta"
            lines={[
              {
                tex: `p(\\theta,\\phi) = \\sin\\theta\\;k\\cos\\theta\\,e^{\\phi} = \\frac{2}{e^{2\\pi}-1}\\cos\\theta\\sin\\theta\\,e^{\\phi}`,
                why: 'the Jacobian sin θ times p(ω), with k from (a)',
              },
              {
                tex: `p(\\theta) = \\int_0^{2\\pi}p(\\theta,\\phi)\\,d\\phi = \\frac{2}{e^{2\\pi}-1}\\cos\\theta\\sin\\theta\\int_0^{2\\pi}e^{\\phi}\\,d\\phi`,
                why: (
                  <>
                    marginalize φ: only e<sup>φ</sup> depends on φ
                  </>
                ),
              },
              {
                tex: `= \\frac{2}{e^{2\\pi}-1}\\cos\\theta\\sin\\theta\\,(e^{2\\pi}-1) = 2\\sin\\theta\\cos\\theta = \\sin 2\\theta`,
                why: (
                  <>
                    the factor e<sup>2π</sup> − 1 cancels; check: ∫₀<sup>π/2</sup> sin 2θ dθ ={' '}
                    {texNumPlain(c.thetaMarginalTotal, 12)}
                  </>
                ),
              },
            ]}
          />
          <Steps
            label="Marginal of φ (Q1b)"
            testId="steps-1b-phi"
            lines={[
              {
                tex: `p(\\phi) = \\int_0^{\\pi/2}p(\\theta,\\phi)\\,d\\theta = \\frac{1}{e^{2\\pi}-1}e^{\\phi}\\int_0^{\\pi/2}2\\cos\\theta\\sin\\theta\\,d\\theta`,
                why: (
                  <>
                    marginalize θ: only cos θ sin θ depends on θ; the 2 of k = 2/(e<sup>2π</sup> − 1) moves
                    inside the integral
                  </>
                ),
              },
              {
                tex: `= \\frac{e^{\\phi}}{e^{2\\pi}-1}\\Big[-\\tfrac12\\cos 2\\theta\\Big]_0^{\\pi/2} = \\frac{e^{\\phi}}{e^{2\\pi}-1}`,
                why: (
                  <>
                    the bracket is {texNumPlain(c.bracket)}, as in (a); check: ∫₀<sup>2π</sup> p(φ) dφ ={' '}
                    {texNumPlain(c.phiMarginalTotal, 12)}
                  </>
                ),
              },
              {
                tex: `p(\\theta,\\phi) = \\sin 2\\theta\\cdot\\frac{e^{\\phi}}{e^{2\\pi}-1} = p(\\theta)\\,p(\\phi)`,
                why: 'separable: θ and φ are independent, so each is sampled from its own CDF',
              },
            ]}
          />
          <KeyNote testId="keynote-stray-ephi">
            in its p(θ) working (the version with the correct identity) the key pulls e<sup>φ</sup> out in
            front of ∫₀<sup>2π</sup> e<sup>φ</sup> dφ while also keeping it inside: a stray e<sup>φ</sup>{' '}
            outside the integral. It survives one more line, p(θ) = 2 cos θ e<sup>φ</sup> sin θ, and then
            disappears; the result p(θ) = sin 2θ is right.
          </KeyNote>
          <h5 className="hemi-subhead">With the identity as printed on the paper</h5>
          <p data-testid="paper-identity">
            The exam paper prints <M t={`p(\\omega) = \\sin\\theta\\,p(\\theta,\\phi)`} />, which is the
            Jacobian upside down. The key works the question both ways and grades leniently (&ldquo;since this
            is confusing&rdquo;): an answer that follows the printed identity correctly gets the marks for the
            procedure. Followed, it gives
          </p>
          <Steps
            label="The paper's identity (Q1b)"
            testId="steps-1b-paper"
            lines={[
              {
                tex: `p(\\theta,\\phi) = \\frac{p(\\omega)}{\\sin\\theta} = \\frac{2}{e^{2\\pi}-1}\\cot\\theta\\,e^{\\phi}`,
                why: 'divide by sin θ instead of multiplying',
              },
              {
                tex: `p(\\theta) = \\frac{2}{e^{2\\pi}-1}\\cot\\theta\\int_0^{2\\pi}e^{\\phi}\\,d\\phi = \\frac{2}{e^{2\\pi}-1}\\cot\\theta\\,(e^{2\\pi}-1) = 2\\cot\\theta`,
                why: "the key's marginal",
              },
              {
                tex: `\\int_0^{\\pi/2}2\\cot\\theta\\,d\\theta = 2\\Big[\\ln\\sin\\theta\\Big]_0^{\\pi/2} = 2\\,(0 - \\ln\\sin 0) = +\\infty`,
                why: (
                  <>
                    not integrable: cot θ ≈ 1/θ near the pole, so p(θ) = 2 cot θ is not a density and has no
                    CDF
                  </>
                ),
              },
              {
                tex: `p(\\phi) = \\frac{2}{e^{2\\pi}-1}e^{\\phi}\\int_0^{\\pi/2}\\cot\\theta\\,d\\theta = \\infty`,
                why: 'where the key stops ("you get infinities"), giving the marks for describing the CDF and inversion steps',
              },
            ]}
          />
          {invertedShown ? (
            <div id="inverted-panel">{inverted}</div>
          ) : (
            <p>
              <button type="button" onClick={onShowInverted} data-testid="show-inverted">
                Work the paper&apos;s identity live (the divergence, plotted)
              </button>
            </p>
          )}
        </DerivationBlock>
        <Answer testId="answer-1b" ask={ask} what="the marginals">
          <p>
            p(θ) = sin 2θ on [0, π/2] and p(φ) = e<sup>φ</sup>/(e<sup>2π</sup> − 1) ={' '}
            {texNumPlain(c.k / 2, 8)} e<sup>φ</sup> on [0, 2π); the histograms in (d) are drawn against these
            curves.
          </p>
        </Answer>
      </ExamPart>

      <ExamPart id="1c" title="CDFs" asks={<>Find the cumulative distribution functions P(θ) and P(φ).</>}>
        <DerivationBlock testId="derivation-1c">
          <Steps
            label="CDF of θ (Q1c)"
            testId="steps-1c-theta"
            lines={[
              {
                tex: `P(\\theta) = \\int_0^{\\theta}\\sin 2\\theta'\\,d\\theta' = \\Big[-\\tfrac12\\cos 2\\theta'\\Big]_0^{\\theta}`,
                why: 'integrate the marginal from 0',
              },
              {
                tex: `= -\\tfrac12(\\cos 2\\theta - \\cos 0) = \\frac{1-\\cos 2\\theta}{2} = \\sin^2\\theta`,
                why: (
                  <>
                    cos 0 = 1; the last form by cos 2θ = 1 − 2 sin²θ. Check: P(π/2) ={' '}
                    {texNumPlain(c.thetaCdfEnd)}
                  </>
                ),
              },
            ]}
          />
          <Steps
            label="CDF of φ (Q1c)"
            testId="steps-1c-phi"
            lines={[
              {
                tex: `P(\\phi) = \\int_0^{\\phi}\\frac{e^{\\phi'}}{e^{2\\pi}-1}\\,d\\phi' = \\frac{1}{e^{2\\pi}-1}\\Big[e^{\\phi'}\\Big]_0^{\\phi} = \\frac{e^{\\phi}-1}{e^{2\\pi}-1}`,
                why: <>e⁰ = 1. Check: P(2π) = {texNumPlain(c.phiCdfEnd)}</>,
              },
            ]}
          />
        </DerivationBlock>
        <Answer testId="answer-1c" ask={ask} what="the CDFs against the samples">
          {xi && ex ? (
            <p data-testid="cdf-example">
              At the first sample of the current set, θ = {texNumPlain(ex.thetaAsin, 8)} and φ ={' '}
              {texNumPlain(ex.phiLog1p, 8)}: P(θ) = {texNumPlain(ex.cdfTheta, 10)} and P(φ) ={' '}
              {texNumPlain(ex.cdfPhi, 10)}, which are its ξ₁ = {texNumPlain(xi.xi1, 10)} and ξ₂ ={' '}
              {texNumPlain(xi.xi2, 10)}: the CDF undoes the inversion of (d).
            </p>
          ) : null}
          {cdfs}
        </Answer>
      </ExamPart>

      <ExamPart
        id="1d"
        title="Sampling by inversion"
        asks={
          <>
            Invert the CDFs to turn two uniform random numbers ξ₁, ξ₂ ∈ [0, 1) into a direction (θ, φ)
            distributed by p(ω).
          </>
        }
      >
        <DerivationBlock testId="derivation-1d">
          <Steps
            label="Invert for θ (Q1d)"
            testId="steps-1d-theta"
            lines={[
              {
                tex: `\\xi_1 = P(\\theta) = \\frac{1-\\cos 2\\theta}{2}`,
                why: 'set the CDF equal to a uniform number',
              },
              { tex: `2\\xi_1 = 1-\\cos 2\\theta \\;\\Rightarrow\\; \\cos 2\\theta = 1-2\\xi_1` },
              {
                tex: `2\\theta = \\cos^{-1}(1-2\\xi_1) \\;\\Rightarrow\\; \\theta = \\tfrac12\\cos^{-1}(1-2\\xi_1)`,
                why: "the key's form",
              },
              {
                tex: `\\xi_1 = \\sin^2\\theta \\;\\Rightarrow\\; \\theta = \\sin^{-1}\\!\\sqrt{\\xi_1}`,
                why: 'the same θ from P(θ) = sin²θ (θ ∈ [0, π/2], so the positive root); equal in exact arithmetic, not in floating point',
              },
            ]}
          />
          <Steps
            label="Invert for φ (Q1d)"
            testId="steps-1d-phi"
            lines={[
              {
                tex: `\\xi_2 = P(\\phi) = \\frac{e^{\\phi}-1}{e^{2\\pi}-1} \\;\\Rightarrow\\; (e^{2\\pi}-1)\\,\\xi_2 + 1 = e^{\\phi}`,
              },
              {
                tex: `\\phi = \\ln\\!\\big[(e^{2\\pi}-1)\\,\\xi_2 + 1\\big] = \\operatorname{log1p}\\!\\big(\\operatorname{expm1}(2\\pi)\\,\\xi_2\\big)`,
                why: 'log1p(x) = ln(1 + x) without losing a small x (the code uses this form)',
              },
            ]}
          />
          {xi && ex ? (
            <Steps
              label="Worked example (Q1d)"
              testId="steps-1d-example"
              lines={[
                {
                  tex: `\\xi_1 = ${texNum(xi.xi1, 8)}:\\quad \\theta = \\tfrac12\\cos^{-1}(1-2\\xi_1) = ${texNum(ex.thetaAcos, 12)}`,
                  why: 'the first sample of the current point set (ringed in the square; the 3D view tracks it)',
                },
                {
                  tex: `\\theta = \\sin^{-1}\\!\\sqrt{\\xi_1} = ${texNum(ex.thetaAsin, 12)}`,
                  why: (
                    <>
                      the other form; the two differ here by{' '}
                      {texNumPlain(Math.abs(ex.thetaAcos - ex.thetaAsin), 2)} (floating point; see the
                      stability panel)
                    </>
                  ),
                },
                {
                  tex: `\\xi_2 = ${texNum(xi.xi2, 8)}:\\quad \\phi = \\ln\\big(${E}\\,\\xi_2 + 1\\big) = ${texNum(ex.phiLn, 12)}`,
                },
              ]}
            />
          ) : null}
        </DerivationBlock>
        <Answer testId="answer-1d" ask={ask} what="the samples' histograms and the χ² test">
          {answer1d}
        </Answer>
      </ExamPart>
      {otherLobe}
    </>
  );
}

/** Plain-text number for prose (formatNumber, no KaTeX). */
function texNumPlain(x: number, digits = 6): string {
  return Number.isFinite(x) ? formatNumber(x, digits) : '—';
}
