/**
 * Exam Q2, part by part: (a) the uniform estimator and why |D| = 2π, (b) the importance estimator,
 * (c) the unbiasedness proof written out, beside the empirical check ("repeat many times").
 */
import type { ReactNode } from 'react';
import { ExamPart, Derivation as DerivationBlock, KeyNote } from '../../../ui/exam';
import { Answer } from '../view/Answer';
import { MathTex, formatNumber } from '../../../ui';
import { Steps } from '../view/Steps';
import { texNum } from '../view/tex';

const M = ({ t }: { t: string }) => <MathTex tex={t} />;

export function Q2({
  solidAngle,
  lobeTex,
  answer2a,
  answer2b,
  answer2c,
  ask,
}: {
  solidAngle: number;
  lobeTex: string;
  answer2a: ReactNode;
  answer2b: ReactNode;
  answer2c: ReactNode;
  /** Results hidden until revealed (`ask=1`). */
  ask: boolean;
}) {
  return (
    <>
      <ExamPart
        id="2a"
        title="Uniform sampling"
        asks={
          <>
            Write the Monte Carlo estimator of I = ∫<sub>Ω</sub> f(ω) dω with directions sampled uniformly
            over the hemisphere.
          </>
        }
      >
        <DerivationBlock testId="derivation-2a">
          <Steps
            label="Uniform estimator (Q2a)"
            testId="steps-2a"
            lines={[
              {
                tex: `\\langle I\\rangle = \\frac{1}{N}\\sum_{i=1}^{N}\\frac{f(X_i)}{p(X_i)},\\qquad p = \\frac{1}{|D|}`,
                why: 'uniform over the domain D: a constant density that integrates to 1',
              },
              { tex: `\\langle I\\rangle = \\frac{|D|}{N}\\sum_{i=1}^{N} f(X_i)`, why: 'f/p = |D| f' },
              {
                tex: `|D| = \\int_\\Omega d\\omega = \\int_0^{2\\pi}\\!\\!\\int_0^{\\pi/2}\\sin\\theta\\,d\\theta\\,d\\phi = 2\\pi\\Big[-\\cos\\theta\\Big]_0^{\\pi/2} = 2\\pi\\,(0+1) = 2\\pi`,
                why: (
                  <>
                    the hemisphere's solid angle, half of the sphere's 4π (computed by quadrature:{' '}
                    {formatNumber(solidAngle, 12)})
                  </>
                ),
              },
              { tex: `\\langle I\\rangle = \\frac{2\\pi}{N}\\sum_{i=1}^{N} f(X_i)` },
            ]}
          />
        </DerivationBlock>
        <Answer testId="answer-2a" ask={ask} what="the uniform estimate">
          {answer2a}
        </Answer>
      </ExamPart>

      <ExamPart
        id="2b"
        title="Importance sampling"
        asks={<>Write the estimator when the directions are drawn from the density p(ω) of Q1.</>}
      >
        <DerivationBlock testId="derivation-2b">
          <Steps
            label="Importance estimator (Q2b)"
            testId="steps-2b"
            lines={[
              {
                tex: `\\langle I\\rangle = \\frac{1}{N}\\sum_{i=1}^{N}\\frac{f(X_i)}{p(X_i)},\\qquad X_i \\sim p`,
                why: 'each sample is weighted by 1/p: directions p favours count for less',
              },
              {
                tex: `p(X_i) = ${lobeTex}`,
                why: 'the density the samples are drawn from (the chosen lobe, per steradian)',
              },
            ]}
          />
          <p>
            It needs <M t={`p(\\omega) > 0`} /> wherever <M t={`f(\\omega) \\neq 0`} /> (see (c)); the
            variance of one term is <M t={`\\int f^2/p\\,d\\omega - I^2`} />, which is small when p is shaped
            like f and can be infinite when p vanishes faster than f.
          </p>
        </DerivationBlock>
        <Answer testId="answer-2b" ask={ask} what="the importance estimate">
          {answer2b}
        </Answer>
      </ExamPart>

      <ExamPart id="2c" title="Unbiasedness" asks={<>Show that the estimator is unbiased: E[⟨I⟩] = I.</>}>
        <DerivationBlock testId="derivation-2c">
          <Steps
            label="Unbiasedness proof (Q2c)"
            testId="steps-2c"
            lines={[
              {
                tex: `E\\big[\\langle I\\rangle\\big] = E\\Big[\\frac{1}{N}\\sum_{i=1}^{N}\\frac{f(X_i)}{p(X_i)}\\Big]`,
              },
              {
                tex: `= \\frac{1}{N}\\sum_{i=1}^{N}E\\Big[\\frac{f(X_i)}{p(X_i)}\\Big]`,
                why: 'linearity of expectation: E[aY] = a E[Y] and E[Y₁ + Y₂] = E[Y₁] + E[Y₂] (no independence needed)',
              },
              {
                tex: `E\\big[g(X)\\big] = \\int g(x)\\,p(x)\\,dx,\\qquad g = \\frac{f}{p}`,
                why: 'the expectation of a function of X (law of the unconscious statistician); each Xᵢ has density p',
              },
              {
                tex: `E\\Big[\\frac{f(X_i)}{p(X_i)}\\Big] = \\int_{p>0}\\frac{f(x)}{p(x)}\\,p(x)\\,dx = \\int_{p>0} f(x)\\,dx`,
                why: 'p cancels where p > 0; samples never land where p = 0',
              },
              {
                tex: `= \\int f(x)\\,dx \\quad\\text{provided } p(x) > 0 \\text{ wherever } f(x) \\neq 0`,
                why: 'otherwise the part of ∫ f where p = 0 is never sampled and the estimator is biased',
              },
              {
                tex: `E\\big[\\langle I\\rangle\\big] = \\frac{1}{N}\\sum_{i=1}^{N}\\int f(x)\\,dx = \\frac{1}{N}\\cdot N\\int f(x)\\,dx = \\int f(x)\\,dx = I`,
              },
            ]}
          />
          <p>
            The uniform estimator of (a) is the case <M t={`p = 1/(2\\pi) > 0`} /> everywhere, so it is
            unbiased for every f.
          </p>
          <KeyNote testId="keynote-eg">
            the key justifies the third step with &ldquo;E[X] = ∫ x · p(x) dx&rdquo;; what is used is the
            expectation of a function of X, E[g(X)] = ∫ g(x) p(x) dx with g = f/p. It also leaves out the
            condition p &gt; 0 wherever f ≠ 0.
          </KeyNote>
        </DerivationBlock>
        <Answer title="Checked empirically" testId="answer-2c" ask={ask} what="the repeated estimates">
          {answer2c}
        </Answer>
      </ExamPart>
    </>
  );
}

/** The chosen lobe's density for the Q2(b) formula. */
export function lobeTexOf(
  lobe: string,
  exponent: number,
  k: number | null,
  customTex: string | null,
  /** Significant digits of k that are right (a typed density's k may have fewer than 6). */
  kDigits = 6,
): string {
  switch (lobe) {
    case 'exam':
      return `k\\cos\\theta_i\\,e^{\\phi_i},\\quad k = ${k !== null ? texNum(k, 8) : '?'}`;
    case 'uniform':
      return `\\frac{1}{2\\pi}`;
    case 'cosine':
      return `\\frac{\\cos\\theta_i}{\\pi}`;
    case 'phong':
      return `\\frac{n+1}{2\\pi}\\cos^{n}\\theta_i,\\quad n = ${texNum(exponent, 6)}`;
    default:
      return customTex
        ? `k\\,\\big(${customTex}\\big),\\quad k = ${k !== null ? texNum(k, Math.min(6, kDigits)) : '?'}`
        : `\\text{(the typed density, not valid yet)}`;
  }
}
