/**
 * Q3(c): the spherical mapping. The point (x, y, z) from the fields, a click on the sphere or the
 * angle sliders (folded: the fields and the sphere are the exam's way); its (u, v) step by step, the bilinear value there, and the same lookup without
 * the normalization (which the key marks down).
 */
import { memo, useCallback, useMemo } from 'react';
import type { SceneProps } from '../../../kit/scene';
import { ScrollBox } from '../../../ui/ScrollBox';
import { Fold } from '../../../ui/Fold';
import {
  keepTextParenthesesTogether,
  DescribedFigure,
  Derivation,
  ExamPart,
  KeyNote,
  LiveAnswer,
  Notice,
  NumberField,
  Readout,
  Revealed,
  Slider,
  Toggle,
} from '../../../ui';
import { KEY_PRINTED, agreesWithKey, isExamSphere, sphereReadouts } from '../readouts';
import { pointAtAngles, round4, sphereAnglesDeg, type SphereModel } from '../sphere';
import type { GridSource, ShownTexture } from '../model';
import type { TextureSchema } from '../params';
import { formatRounded } from '../../../core/format';
import { describeSphere } from '../view/describe';
import { SphereView } from '../view/SphereView';
import { MathSteps, SphereBilinear, sphereBlocks } from '../view/WorkedSteps';
import { keyNote, texPlain } from './shared';
import './Q3c.css';

type Props = Pick<SceneProps<TextureSchema>, 'params' | 'setParams'> &
  ShownTexture & {
    sphere: SphereModel;
    src: GridSource;
    present: boolean;
    /** Ask first: the angles, the steps and the answer hidden until revealed. */
    ask: boolean;
  };

/** The angle sliders: a keyboard way to move the point on the sphere. */
const ANGLES = [
  { key: 'phi', label: 'Azimuth φ (moves the point)', max: 359.9 },
  { key: 'theta', label: 'Polar angle θ (moves the point)', max: 180 },
] as const;

export const Q3c = memo(function Q3c({ params, setParams, sphere, src, present, ask, ...shown }: Props) {
  const { opts } = shown;
  const ro = useMemo(() => sphereReadouts(sphere), [sphere]);
  const examS = isExamSphere(src, opts, sphere);
  const dir = useMemo<[number, number, number] | null>(() => {
    if (!sphere.ok) return null;
    return [params.x / sphere.r, params.y / sphere.r, params.z / sphere.r];
  }, [sphere, params.x, params.y, params.z]);
  const onPick = useCallback(
    (p: [number, number, number]) => setParams({ x: round4(p[0]), y: round4(p[1]), z: round4(p[2]) }),
    [setParams],
  );
  // where the sphere point is, as angles (a keyboard path to "picking" a point on the sphere)
  const angles = sphereAnglesDeg(sphere);
  const setAngles = (a: { phi: number; theta: number }) =>
    setParams(pointAtAngles(sphere.ok ? sphere.r : 1, a.phi, a.theta));
  const n = params.normalize;

  return (
    <ExamPart
      id="3c"
      title="The spherical mapping"
      asks={
        <>
          A point on a sphere, x = r cos u sin v, y = r sin u sin v, z = r cos v, has y/x = 1 and z/r = √2/2.
          Find its texture coordinates (u, v) and the bilinear value there.
        </>
      }
    >
      <div className="tx-sphere-cols">
        <div className="tx-sphere-inputs">
          {(['x', 'y', 'z'] as const).map((k) => (
            <NumberField
              key={k}
              label={k}
              value={params[k]}
              min={-1000}
              max={1000}
              onChange={(x) => setParams({ [k]: x })}
              testId={`${k}-field`}
            />
          ))}
          {/* the angles are what (c) asks for: not shown before the reveal */}
          {ask ? null : (
            <Fold name="angles" summary="Move it by angles φ, θ" className="tx-fold">
              {ANGLES.map(({ key, label, max }) => (
                <Slider
                  key={key}
                  label={label}
                  unit="°"
                  value={round4(angles[key])}
                  min={0}
                  max={max}
                  step={0.1}
                  onChange={(x) => setAngles({ ...angles, [key]: x })}
                  testId={`${key}-slider`}
                />
              ))}
            </Fold>
          )}
          <Toggle
            label="Normalize by (2π, π)"
            checked={n}
            onChange={(x) => setParams({ normalize: x })}
            testId="normalize-toggle"
          />
          <button
            type="button"
            onClick={() => setParams({ x: 1, y: 1, z: Math.SQRT2 })}
            data-testid="exam-point"
          >
            The exam’s point {keepTextParenthesesTogether('(y/x = 1, z/r = √2/2)')}
          </button>
        </div>
        <div className="tx-sphere-fig">
          <DescribedFigure
            label="The sphere wearing the texture, with the chosen point"
            description={
              `${describeSphere(sphere, params, n, ask)} The seam, where u jumps from just below 1 back to 0, ` +
              'is the meridian φ = 0 through +x; the pole axis is z.'
            }
            testId="sphere-figure"
          >
            <SphereView {...shown} normalize={n} dir={dir} onPick={onPick} height={present ? 420 : 320} />
          </DescribedFigure>
          <p className="tx-small">
            Click the sphere to pick a point, or use the x, y, z fields{ask ? '' : ' or the angles'}.
          </p>
        </div>
      </div>
      <Revealed ask={ask} what="the steps and the answer" minHeight="6rem">
        {!sphere.ok ? (
          <Notice kind="warn" testId="sphere-error">
            <strong>x, y, z</strong>: {sphere.message} The sphere readouts show “none” until you pick another
            point.
          </Notice>
        ) : (
          <Derivation testId="derivation-3c">
            <p className="tx-small">
              Divide y by x to eliminate r and v, and z by r to isolate v. The key writes u = arctan(y/x);
              atan2(y, x) is the same for x &gt; 0 and also finds the right quadrant when x ≤ 0 (negative
              angles get + 2π, so u ∈ [0, 2π)). Then normalize by the ranges (2π, π) of the two angles to land
              in [0, 1]:
            </p>
            <MathSteps
              label="Spherical coordinates, step by step"
              steps={sphereBlocks({
                x: params.x,
                y: params.y,
                z: params.z,
                r: sphere.r,
                phi: sphere.phi,
                theta: sphere.theta,
                pole: sphere.pole,
                u: sphere.normalized.u,
                v: sphere.normalized.v,
              })}
            />
            <p className="tx-small">
              Bilinear at the normalized (u, v), in the key’s form (each step divided by the cell size):
            </p>
            <SphereBilinear q={sphere.normalized} opts={opts} />
            {sphere.normalized.bil.fv === 0 || sphere.normalized.bil.fu === 0 ? (
              <p className="tx-small">
                The point lies on a node line ({sphere.normalized.bil.fv === 0 ? 'v = v₀' : 'u = u₀'}), so one
                of the two rows gets weight 0: that is the key’s one-line form.
              </p>
            ) : null}
          </Derivation>
        )}
        <LiveAnswer testId="answer-3c">
          <div className="tx-sphere-answer">
            <div className="readouts">
              <Readout id="sphere-u" label={n ? 'u = φ / 2π' : 'u = φ (radians)'} value={ro.sphereU} />
              <Readout id="sphere-v" label={n ? 'v = θ / π' : 'v = θ (radians)'} value={ro.sphereV} />
              <Readout
                id="sphere-bilinear"
                label={n ? 'Bilinear at (u, v)' : 'Bilinear at (φ, θ), not normalized'}
                value={ro.sphereBilinear}
                note={
                  examS && ro.sphereBilinear !== null
                    ? keyNote(ro.sphereBilinear, n ? KEY_PRINTED.sphere : KEY_PRINTED.sphereRaw)
                    : undefined
                }
              />
            </div>
            {sphere.ok ? <SphereCompare sphere={sphere} /> : null}
          </div>
        </LiveAnswer>
        {sphere.ok ? (
          <KeyNote testId="key-note">
            the key cuts 2.5 marks when the normalization is missing, but gives full marks for a lookup at the
            un-normalized (π/4, π/4) done right, and prints {KEY_PRINTED.sphereRaw.value} for it.{' '}
            {examS ? (
              <ExamSphereNote normalized={sphere.normalized.bil.value} raw={sphere.raw.bil.value} />
            ) : (
              `Here the un-normalized lookup gives ${texPlain(sphere.raw.bil.value)}.`
            )}
          </KeyNote>
        ) : null}
      </Revealed>
    </ExamPart>
  );
});

/** The sphere point normalized and not, side by side. */
function SphereCompare({ sphere }: { sphere: Extract<SphereModel, { ok: true }> }) {
  const { normalized: a, raw: b } = sphere;
  return (
    <ScrollBox label="The sphere point, normalized and not (the table scrolls sideways on narrow screens)">
      <table className="worked tx-compare" data-testid="sphere-compare">
        <thead>
          <tr>
            <th />
            <th>normalized</th>
            <th>forgot to normalize</th>
          </tr>
        </thead>
        <tbody>
          <tr>
            <th>u</th>
            <td>{texPlain(a.u)}</td>
            <td>{texPlain(b.u)}</td>
          </tr>
          <tr>
            <th>v</th>
            <td>{texPlain(a.v)}</td>
            <td>{texPlain(b.v)}</td>
          </tr>
          <tr>
            <th>(u, v) as used</th>
            <td>
              ({formatRounded(a.bil.u)}, {formatRounded(a.bil.v)})
            </td>
            <td>
              ({formatRounded(b.bil.u)}, {formatRounded(b.bil.v)})
            </td>
          </tr>
          <tr>
            <th>bilinear</th>
            <td data-testid="sphere-normalized-value">{texPlain(a.bil.value)}</td>
            <td data-testid="sphere-raw-value">{texPlain(b.bil.value)}</td>
          </tr>
        </tbody>
      </table>
    </ScrollBox>
  );
}

function ExamSphereNote({ normalized, raw }: { normalized: number; raw: number }) {
  const closed = 21 - 4 * Math.PI;
  const { sphere: printed, sphereRaw: printedRaw } = KEY_PRINTED;
  return (
    <span className="tx-note-text">
      On the exam’s grid the texture is the linear function 21 + 4u − 20v, which bilinear filtering reproduces
      exactly. Normalized, (1/8, 1/4) gives {texPlain(normalized)} (
      {agreesWithKey(normalized, printed) ? 'as the key prints' : `the key prints ${printed.value}`}
      ). Not normalized, (π/4, π/4) ≈ (0.785, 0.785) is still inside [0, 1], so no addressing is involved, and
      the value is 21 − 4π = {texPlain(closed)}; this lookup gives {texPlain(raw)}.{' '}
      {agreesWithKey(raw, printedRaw)
        ? `The key’s ${printedRaw.value} agrees.`
        : `The key prints ${printedRaw.value}, which differs in the second decimal ` +
          `(the exact value rounds to ${raw.toFixed(2)}).`}
    </span>
  );
}
