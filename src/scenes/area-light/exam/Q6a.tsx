/**
 * Q6(a): dω = dA cos θₗ / r² by similar triangles, each step with this patch's numbers, the
 * cross-section figure with the patch's controls, and the live check of the formula against the
 * exact solid angle of the patch (how the difference shrinks with the patch is one click away).
 */
import { memo } from 'react';
import { Derivation, ExamPart, LiveAnswer, MathTex, Revealed } from '../../../ui';
import { Fold } from '../../../ui/Fold';
import type { PatchModel } from '../patch';
import type { AreaLightParams } from '../params';
import { fmt } from '../view/format';
import { PatchPanel, type PatchValues } from '../view/PatchPanel';
import { ReadoutList } from '../view/ReadoutList';
import { PatchErrorPlot } from '../view/PatchErrorPlot';

const APPROX_LABEL = (
  <>
    dA cos θ<sub>l</sub> / r²
  </>
);
const COS_LABEL = (
  <>
    cos θ<sub>l</sub>
  </>
);

export const Q6a = memo(function Q6a({
  patch,
  values,
  set,
  ask,
}: {
  patch: PatchModel;
  values: PatchValues;
  set: (patch: Partial<AreaLightParams>) => void;
  /** Asked to predict first: the check is hidden until revealed. */
  ask: boolean;
}) {
  return (
    <ExamPart
      id="6a"
      title="Solid angle of a small area element"
      asks={
        <>
          A small area element dA of a light, at distance r from x, arbitrarily oriented (normal n<sub>l</sub>{' '}
          at angle θ<sub>l</sub> to the direction back to x), subtends a solid angle dω. Show that{' '}
          <MathTex tex={String.raw`d\omega = \dfrac{dA\cos\theta_l}{r^2}`} />.
        </>
      }
    >
      <Derivation testId="derivation-6a">
        <ol className="al-steps">
          <li>
            Project dA onto the plane perpendicular to the ray: a perpendicular element{' '}
            <MathTex tex={String.raw`dA^{\perp}`} /> with sides dl, so{' '}
            <MathTex tex={String.raw`dA^{\perp} = dl\cdot dl = dA\cos\theta_l`} />
            <span className="al-live" data-testid="step-6a-perp">
              {' '}
              (here dA = {fmt(patch.area)}, cos θ<sub>l</sub> = {fmt(patch.cosThetaL)}, dA⊥ ={' '}
              {fmt(patch.area * patch.cosThetaL)}, dl = {fmt(Math.sqrt(patch.area * patch.cosThetaL))})
            </span>
            .
          </li>
          <li>
            The solid-angle element is the patch dA⊥ casts on the unit sphere, with sides dω<sub>l</sub>:{' '}
            <MathTex tex={String.raw`d\omega = d\omega_l\cdot d\omega_l`} />.
          </li>
          <li>
            By similar triangles (shaded in the figure: legs 1 and dω<sub>l</sub>/2 on the unit circle, legs r
            and dl/2 at the patch):{' '}
            <MathTex
              tex={String.raw`\frac{d\omega_l/2}{1} = \frac{dl/2}{r}\;\Rightarrow\; d\omega_l = \frac{dl}{r}`}
            />
            <span className="al-live" data-testid="step-6a-similar">
              {' '}
              (r = {fmt(patch.r)}: dω<sub>l</sub> = {fmt(Math.sqrt(patch.area * patch.cosThetaL) / patch.r)})
            </span>
            .
          </li>
          <li>
            Thus{' '}
            <MathTex
              tex={String.raw`d\omega = \frac{dl}{r}\cdot\frac{dl}{r} = \frac{dA^{\perp}}{r^2} = \frac{dA\cos\theta_l}{r^2}`}
            />
            <span className="al-live" data-testid="step-6a-result">
              {' '}
              = {fmt(patch.approx, 6)} sr for this patch
            </span>
            .
          </li>
        </ol>
      </Derivation>
      <div className="al-6a">
        <PatchPanel patch={patch} values={values} set={set} />
        <Revealed ask={ask} what="the check of the formula against the exact solid angle">
          <LiveAnswer title="Check, computed live: the formula against the exact Ω" testId="answer-6a">
            <p className="al-note">
              Exact only in the limit of a small patch: the exact solid angle Ω of the orange patch (Van
              Oosterom–Strackee) and dA cos θ<sub>l</sub> / r² differ by a fraction that falls like the square
              of the patch’s size.
            </p>
            <ReadoutList
              className="al-check-readouts"
              items={[
                {
                  id: 'patch-exact',
                  label: 'exact Ω of the patch',
                  value: patch.exact,
                  digits: 8,
                  unit: 'sr',
                },
                { id: 'patch-approx', label: APPROX_LABEL, value: patch.approx, digits: 8, unit: 'sr' },
                { id: 'patch-rel-error', label: 'relative difference', value: patch.relError, digits: 3 },
                { id: 'patch-r', label: 'r', value: patch.r, digits: 5 },
                { id: 'patch-cos', label: COS_LABEL, value: patch.cosThetaL, digits: 5 },
              ]}
            />
            <Fold name="patch-error" summary="The difference against the patch side">
              <PatchErrorPlot patch={patch} />
            </Fold>
          </LiveAnswer>
        </Revealed>
      </div>
    </ExamPart>
  );
});
