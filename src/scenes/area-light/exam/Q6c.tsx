/**
 * Q6(c): the pdf and the Monte Carlo estimator of uniform area sampling, worked through the first
 * four samples of the seed, then the live answer (Answer6c).
 */
import { TTestLine } from '../../../ui/TTestLine';
import { memo, useMemo, type ReactNode } from 'react';
import type { LightStrategy } from '../../../core/lights';
import { Derivation, ExamPart, LiveAnswer, MathTex, Readout, Revealed } from '../../../ui';
import { STRATEGY_LABEL } from '../strategies';
import { estimateOne, givenSamples, type AreaLightModel, type StrategyEstimate } from '../model';
import { fmt } from '../view/format';
import { ScrollBox } from '../../../ui/ScrollBox';

export const Q6c = memo(function Q6c({
  model,
  seed,
  answer,
  ask,
}: {
  model: AreaLightModel;
  seed: number;
  /** The live answer, rendered when the part's body mounts. */
  answer: ReactNode;
  /** Asked to predict first: the terms, their mean and the answer are hidden until revealed. */
  ask: boolean;
}) {
  const given = useMemo(() => givenSamples(model, seed, 4), [model, seed]);
  const fArea = given.f;
  return (
    <ExamPart
      id="6c"
      title="Monte Carlo estimator with uniform area sampling"
      asks={
        <>
          Sampling points uniformly on the light’s area, give the pdf and the Monte Carlo estimator of L
          <sub>o</sub>.
        </>
      }
    >
      <Derivation testId="derivation-6c">
        <ol className="al-steps">
          <li>
            The pdf is uniform over the light’s area: <MathTex tex={String.raw`p_A = \frac{1}{|A|}`} />
            <span className="al-live" data-testid="step-6c-pdf">
              {' '}
              (|A| = {fmt(given.area)}, p<sub>A</sub> = {fmt(1 / given.area)})
            </span>
            .
          </li>
          <li>
            The MC estimator divides each term of the area integral by p<sub>A</sub>:
            <MathTex
              display
              tex={String.raw`\langle L_o\rangle = \frac{1}{N}\sum_{i=1}^{N}\frac{f\,L_i\,V\cos\theta_i\,\cos\theta_{l,i}/r_i^2}{p_A} = \frac{|A|}{N}\sum_{i=1}^{N} f\,L_i\,V_i\cos\theta_i\,\frac{\cos\theta_{l,i}}{r_i^2}`}
            />
          </li>
          <li>
            With numbers — the first four samples of seed {seed} (f = ρ/π = {fmt(fArea)}, L = {fmt(model.L)}
            ):
            <ScrollBox label="The first four samples (the table scrolls sideways on narrow screens)">
              <table className="al-table al-given" data-testid="given-samples">
                <thead>
                  <tr>
                    <th scope="col">i</th>
                    <th scope="col">(ξ₁, ξ₂)</th>
                    <th scope="col">
                      y<sub>i</sub> on the light
                    </th>
                    <th scope="col">
                      r<sub>i</sub>
                    </th>
                    <th scope="col">
                      cos θ<sub>i</sub>
                    </th>
                    <th scope="col">
                      cos θ<sub>l,i</sub>
                    </th>
                    <th scope="col">
                      V<sub>i</sub>
                    </th>
                    <th scope="col">
                      |A| f L V cos θ cos θ<sub>l</sub> / r²
                    </th>
                  </tr>
                </thead>
                <tbody>
                  {given.samples.map((g, i) => (
                    <tr key={i} data-testid={`given-${i + 1}`}>
                      <th scope="row">{i + 1}</th>
                      <td>
                        {fmt(g.u1, 3)}, {fmt(g.u2, 3)}
                      </td>
                      <td>
                        ({fmt(g.x[0], 3)}, {fmt(g.x[1], 3)}, {fmt(g.x[2], 3)})
                      </td>
                      <td>{fmt(g.r)}</td>
                      <td>{fmt(g.cosTheta)}</td>
                      <td>{fmt(g.cosThetaL)}</td>
                      <td>{g.V}</td>
                      {ask ? (
                        <td>?</td>
                      ) : (
                        <td data-testid={`given-term-${i + 1}`} data-value={String(g.term)}>
                          {fmt(g.term, 5)}
                        </td>
                      )}
                    </tr>
                  ))}
                </tbody>
              </table>
            </ScrollBox>
            <Revealed ask={ask} what="the four terms and their mean">
              <MathTex
                display
                tex={String.raw`\langle L_o\rangle_{N=4} = \tfrac{1}{4}\big(${given.samples.map((g) => fmt(g.term, 5)).join(' + ')}\big) = ${fmt(given.estimate, 5)}`}
              />
              <Readout
                id="given-estimate"
                label={
                  <>
                    ⟨L<sub>o</sub>⟩ from these 4 samples
                  </>
                }
                value={given.estimate}
                digits={7}
              />
            </Revealed>
          </li>
        </ol>
      </Derivation>
      <Revealed ask={ask} what="the estimate with N samples and its verdict">
        {answer}
      </Revealed>
    </ExamPart>
  );
});

/**
 * Q6(c)'s live answer: the chosen strategy's estimate with n samples (on the main thread up to
 * the scene's limit, else from the worker's list), its standard error and the verdict against the reference.
 */
export const Answer6c = memo(function Answer6c({
  model,
  strategy,
  n,
  seed,
  big,
  estimates,
  pending,
  reference: target,
}: {
  model: AreaLightModel;
  strategy: LightStrategy;
  n: number;
  seed: number;
  big: boolean;
  estimates: StrategyEstimate[] | null;
  pending: boolean;
  reference: number;
}) {
  const chosenSync = useMemo(
    () => (big ? null : estimateOne(model, strategy, n, seed)),
    [big, model, strategy, n, seed],
  );
  const chosen: StrategyEstimate = chosenSync ??
    estimates?.find((e) => e.strategy === strategy) ?? { strategy, estimate: NaN, stderr: NaN, n };
  const zTarget =
    Number.isFinite(target) && chosen.stderr > 0 ? (chosen.estimate - target) / chosen.stderr : null;
  return (
    <LiveAnswer testId="answer-6c">
      <div className="al-readouts">
        <Readout
          id="estimate"
          label={`estimate, ${STRATEGY_LABEL[strategy]}, n = ${n}`}
          value={chosen.estimate}
          digits={7}
        />
        <Readout id="stderr" label="standard error" value={chosen.stderr} digits={3} />
        <Readout
          id="reference-6c"
          label={model.occluder ? 'reference (with occluder)' : 'reference (Lambert)'}
          value={Number.isFinite(target) ? target : null}
          digits={7}
        />
      </div>
      {!pending && Number.isFinite(target) && Number.isFinite(chosen.estimate) ? (
        <TTestLine
          estimate={chosen.estimate}
          stderr={chosen.stderr}
          n={chosen.n}
          exact={target}
          against={model.occluder ? 'the occluded reference' : 'Lambert’s exact irradiance'}
        />
      ) : null}
      <p className="al-verdict" data-testid="al-verdict">
        {pending ? (
          <>
            <progress aria-label="Estimating" /> Estimating with n = {n} samples per strategy in the
            background…
          </>
        ) : zTarget === null ? (
          chosen.stderr === 0 && chosen.estimate === target ? (
            'Every sample gave the same value: the estimate is exact here.'
          ) : (
            'No standard error yet (n < 2), or no analytic value to compare with.'
          )
        ) : (
          // the distance only: the t-test above gives the verdict
          `The estimate is ${fmt(Math.abs(zTarget), 2)} standard errors ${zTarget >= 0 ? 'above' : 'below'} the ${model.occluder ? 'occluded ' : ''}reference.`
        )}
      </p>
    </LiveAnswer>
  );
});
