/**
 * Q6(b): the rendering equation rewritten from solid angle to the light's area, the Jacobian and the
 * visibility highlighted, with the reference values of the current setup.
 */
import { memo, useMemo } from 'react';
import { Derivation, ExamPart, KeyNote, LiveAnswer, MathTex, Readout, Revealed } from '../../../ui';
import type { AreaLightModel } from '../model';
import type { PatchModel } from '../patch';
import { fmt } from '../view/format';

/** Highlight colours of the boxes (Jacobian, visibility): light boxes with dark text, or dark with light. */
function highlight(dark: boolean) {
  return dark
    ? { jBg: '#5c3412', jFg: '#fde2c8', vBg: '#1e4628', vFg: '#d7ecd9' }
    : { jBg: '#fde2c8', jFg: '#1c1d21', vBg: '#d7ecd9', vFg: '#1c1d21' };
}

export const Q6b = memo(function Q6b({
  patch,
  model,
  dark,
  ask,
}: {
  patch: PatchModel;
  model: AreaLightModel;
  dark: boolean;
  /** Asked to predict first: the values of Lₒ are hidden until revealed. */
  ask: boolean;
}) {
  const hl = useMemo(() => highlight(dark), [dark]);
  return (
    <ExamPart
      id="6b"
      title="The rendering equation over the light’s area"
      asks={
        <>
          Rewrite the rendering equation, an integral over solid angle, as an integral over the area A of the
          light.
        </>
      }
    >
      <Derivation testId="derivation-6b">
        <ol className="al-steps">
          <li>
            Over directions:{' '}
            <MathTex
              display
              tex={String.raw`L_o(x,\omega_o) = \int_{\Omega} f(x,\omega_o,\omega_i)\,L_i(x,\omega_i)\cos\theta\,d\omega_i`}
            />
          </li>
          <li>
            Change of variables from ω<sub>i</sub> to the point y on the light: dω<sub>i</sub> = J<sub>T</sub>{' '}
            dA, which introduces a Jacobian:
            <MathTex
              display
              tex={String.raw`L_o(x,\omega_o) = \int_{A} f\,L_i\cos\theta\,\colorbox{${hl.jBg}}{$\color{${hl.jFg}}J_T$}\,dA`}
            />
          </li>
          <li>
            Over points of the light, nothing says whether the segment from x to y is blocked (over
            directions, L<sub>i</sub> already included it), so visibility is added explicitly:
            <MathTex
              display
              tex={String.raw`L_o(x,\omega_o) = \int_{A} f\,L_i\,\colorbox{${hl.vBg}}{$\color{${hl.vFg}}V(x,y)$}\cos\theta\,J_T\,dA`}
            />
          </li>
          <li>
            The Jacobian is Q6(a)’s dω/dA:
            <MathTex
              display
              tex={String.raw`L_o(x,\omega_o) = \int_{A} f\,L_i\,\colorbox{${hl.vBg}}{$\color{${hl.vFg}}V(x,y)$}\,\cos\theta\,\colorbox{${hl.jBg}}{$\color{${hl.jFg}}\dfrac{\cos\theta_l}{r^2}$}\,dA_y`}
            />
            <span className="al-live" data-testid="step-6b-jacobian">
              For the patch of (a): J<sub>T</sub> = cos θ<sub>l</sub> / r² ={' '}
              {fmt(patch.cosThetaL / (patch.r * patch.r))} per unit area.
            </span>
          </li>
        </ol>
        <p>
          The{' '}
          <span className="al-hl-j">
            Jacobian cos θ<sub>l</sub> / r²
          </span>{' '}
          turns area into solid angle; the <span className="al-hl-v">visibility V</span> is 1 where y is seen
          from x and 0 where it is blocked.
        </p>
        <KeyNote testId="keynote-6b">
          the key writes L<sub>i</sub>(x, ω<sub>i</sub>) and V(x, ω<sub>i</sub>) inside the area integral;
          over A they are functions of the point y on the light (ω<sub>i</sub> is the direction from x to y),
          as written here.
        </KeyNote>
      </Derivation>
      <Revealed ask={ask} what="Lₒ and the light’s solid angle">
        <LiveAnswer testId="answer-6b">
          <div className="al-readouts">
            <Readout
              id="reference"
              label="reference (Lambert, no occluder)"
              value={model.reference}
              digits={7}
            />
            <Readout
              id="reference-occluded"
              label="reference with occluder (V < 1)"
              value={model.occluder ? model.referenceOccluded : null}
              digits={7}
            />
            <Readout
              id="projected-solid-angle"
              label="∫ cos θ dω (clipped to the horizon)"
              value={model.projectedSolidAngle}
              digits={7}
              unit="sr"
            />
            <Readout
              id="solid-angle"
              label="solid angle Ω of the light"
              value={model.solidAngle}
              digits={7}
              unit="sr"
            />
            <Readout
              id="solid-angle-closed"
              label="Ω, closed form (light parallel to floor)"
              value={model.solidAngleClosed}
              digits={7}
              unit="sr"
            />
          </div>
          <p className="al-note">
            For a Lambertian floor f = ρ/π, and the integral has a closed form: L<sub>o</sub> = (ρ/π) L ∫ cos
            θ dω by Lambert’s formula.
          </p>
        </LiveAnswer>
      </Revealed>
    </ExamPart>
  );
});
