/**
 * Q5's written derivation with the numbers of the current ray: substitute, expand, the
 * coefficients, the roots, the two conditions the key marks (Δ ≥ 0, t ≥ 0), the hit, and why a
 * renderer tests t > t_min (with a survey of secondary rays over the sphere).
 */
import { memo } from 'react';
import { Derivation, MathTex } from '../../../ui';
import type { RaySphereMethod } from '../../../core/geometry';
import { activeRows, type RaySphereModel } from '../model';
import { secondaryFromHit, tMinFor } from '../secondaryRay';
import { fmt, tx, txVec as v, yes } from '../view/format';
import { SURVEY_POINTS, useSurvey } from '../view/useSurvey';

/** The derivation block: while the sweep plays it holds the numbers of where the sweep started. */
export function Q5Derivation({ model, playing }: { model: RaySphereModel; playing: boolean }) {
  return (
    <Derivation testId="derivation">
      {playing ? (
        <p className="rs-small" data-testid="derivation-held">
          The numbers below are those of the position where the sweep started; they follow the animation when
          you pause it.
        </p>
      ) : null}
      <DerivationSteps model={model} />
    </Derivation>
  );
}

/** `Δ ≥ 0 ✓` or `Δ < 0 ✗` (and likewise for a root): the condition, tested, in TeX. */
const test = (name: string, x: number, digits: number) =>
  `${name} = ${tx(x, digits)} ${x >= 0 ? '\\ge 0' : '< 0'}${yes(x >= 0)}`;

/** Memoised on the (throttled, held) model: a frame of the animation does not re-render it. */
const DerivationSteps = memo(function DerivationSteps({ model }: { model: RaySphereModel }) {
  const res = model.chosen;
  const [cx, cy, cz] = model.input.c;
  if (!res) return <p>No derivation: the inputs overflow.</p>;
  const { o, d, c, r } = model.input;
  const naive = activeRows(model).rows.find((x) => x.method === 'naive')!.res;
  const textbookDisc = naive.discriminant; // = b² − 4ac of the shown a, b, c, in the model's arithmetic
  const robust = res.method === 'stable';
  const arith = model.precision === 'f32' ? 'float32' : 'double';
  const roots =
    res.t0 === null
      ? `\\Delta < 0 \\;\\Rightarrow\\; \\text{no real root: the line misses the sphere}`
      : res.t0 === res.t1
        ? `t_0 = t_1 = -\\frac{b}{2a} = ${tx(res.t0, 8)}`
        : `{t_{0} = \\frac{-b - \\sqrt{\\Delta}}{2a} = ${tx(res.t0, 8)}},\\allowbreak\\qquad ` +
          `{t_{1} = \\frac{-b + \\sqrt{\\Delta}}{2a} = ${tx(res.t1, 8)}}`;
  const condDisc = test('\\Delta', res.discriminant, 6);
  const condT =
    res.t0 === null || res.t1 === null
      ? `\\text{(no roots to test)}`
      : `{${test('t_0', res.t0, 6)}},\\allowbreak\\qquad {${test('t_1', res.t1, 6)}}`;
  const hit =
    res.tHit === null
      ? `\\text{no root } t \\ge 0 \\;\\Rightarrow\\; \\text{no hit}`
      : `t_{\\text{hit}} = \\min\\{\\, t_i : t_i \\ge 0 \\,\\} = ${tx(res.tHit, 8)}`;
  const sec = secondaryFromHit(model.input, res, res.method);
  const tMin = tMinFor(r);
  return (
    <div className="rs-derivation" data-testid="q5-derivation">
      <ol className="rs-steps">
        <li data-testid="step-substitute">
          <p>
            A point of the ray is p(t) = o + t d. It lies on the sphere when its distance to the centre C is
            r; square both sides and substitute the ray:
          </p>
          <MathTex
            display
            tex={
              `\\lVert \\mathbf p - \\mathbf C \\rVert^2 = r^2 \\quad\\Rightarrow\\quad ` +
              `\\lVert \\mathbf o + t\\,\\mathbf d - \\mathbf C \\rVert^2 = r^2`
            }
          />
        </li>
        <li data-testid="step-expand">
          <p>Write f = o − C and expand the squared length as a dot product with itself:</p>
          <MathTex
            display
            tex={
              `(\\mathbf f + t\\,\\mathbf d)\\cdot(\\mathbf f + t\\,\\mathbf d) = ` +
              `(\\mathbf d\\cdot\\mathbf d)\\,t^2 + 2\\,(\\mathbf d\\cdot\\mathbf f)\\,t + \\mathbf f\\cdot\\mathbf f = r^2`
            }
          />
          <p>so t solves a quadratic:</p>
          <MathTex
            display
            tex={
              `{a t^2 + b t + c = 0},\\allowbreak\\qquad {a = \\mathbf d\\cdot\\mathbf d},\\allowbreak\\quad ` +
              `{b = 2\\,\\mathbf d\\cdot(\\mathbf o - \\mathbf C)},\\allowbreak\\quad ` +
              `{c = \\lVert \\mathbf o - \\mathbf C\\rVert^2 - r^2}`
            }
          />
        </li>
        <li data-testid="step-numbers">
          <p>
            With o = <MathTex tex={v(o)} />, d = <MathTex tex={v(d)} />, C = <MathTex tex={v(c)} />, r ={' '}
            <MathTex tex={tx(r, 6)} />:
          </p>
          <MathTex
            display
            tex={`{a = ${tx(res.a)}},\\allowbreak\\qquad {b = ${tx(res.b)}},\\allowbreak\\qquad {c = ${tx(res.c)}}`}
          />
        </li>
        <li data-testid="step-roots">
          <p>The quadratic formula gives the roots, with the discriminant Δ:</p>
          <MathTex
            display
            tex={
              `{t = \\frac{-b \\pm \\sqrt{\\Delta}}{2a}},\\allowbreak\\qquad \\Delta = b^2 - 4ac = ` +
              `(${tx(res.b)})^2 - 4\\,(${tx(res.a)})(${tx(res.c)}) = ${tx(textbookDisc)}`
            }
          />
          {robust ? (
            <p className="rs-small" data-testid="step-robust-note">
              {textbookDisc === res.discriminant
                ? `That is b² − 4ac of these numbers in ${arith} arithmetic; the robust form (used for the roots ` +
                  'here, see “Explore further”) gives the same value.'
                : `That is b² − 4ac of these numbers in ${arith} arithmetic (the textbook method). The roots ` +
                  'below use the robust form, which computes Δ = 4a(r²\u00a0−\u00a0|ℓ|²) = ' +
                  `${fmt(res.discriminant)}, where ℓ = f − (f·d\u00a0/\u00a0d·d) d with f = o − C is the vector from ` +
                  'the centre to the point of the ray’s line nearest to it, ' +
                  'without cancellation: the same quantity, different rounding.'}
            </p>
          ) : null}
          <MathTex display tex={roots} />
        </li>
        <li data-testid="step-conditions">
          <p>
            <strong>Conditions for a hit</strong> (the marks):
          </p>
          <ul>
            <li>
              <strong>Δ ≥ 0</strong>: the quadratic has real roots, i.e. the <em>line</em> meets the sphere (Δ
              = 0: it touches it, a double root). <MathTex tex={condDisc} />
            </li>
            <li>
              <strong>t ≥ 0</strong>: a ray only goes forward from its origin, so a root with t &lt; 0 is a
              meeting point <em>behind</em> the origin and does not count. <MathTex tex={condT} />
            </li>
          </ul>
        </li>
        <li data-testid="step-hit">
          <p>
            The hit is the <strong>nearest non-negative root</strong>: t₀ if t₀ ≥ 0 (the ray enters there),
            otherwise t₁ if t₁ ≥ 0 (the origin is inside the sphere: the ray leaves at t₁), otherwise none.
          </p>
          <MathTex display tex={hit} />
        </li>
        <li data-testid="step-tmin">
          <p>
            <strong>
              Why renderers test t &gt; t<sub>min</sub> (a small positive number) instead of t ≥ 0.
            </strong>{' '}
            A shadow or reflection ray starts at a hit point on the surface. That point is computed in
            floating point, so it lies a rounding error inside or outside the sphere, and the quadratic then
            has a root t ≈ 0 at the starting point itself. With t ≥ 0 that root can count as a hit: the
            surface shadows itself (“shadow acne”, a speckle of dark dots). Testing t &gt; t<sub>min</sub>,
            here t<sub>min</sub> = 10⁻⁴ r = {fmt(tMin)}, skips it.
          </p>
          {sec ? (
            <p data-testid="tmin-example">
              Here: the hit point p = o + t<sub>hit</sub> d = <MathTex tex={v(sec.p)} /> lies |p − C| − r ={' '}
              {fmt(sec.offSurface)} off the surface. A ray leaving it along the outward normal (towards a
              light straight above) has roots t = {fmt(sec.res.t0)} and {fmt(sec.res.t1)}: the first is the
              far side of the sphere behind it, the second is <em>p itself</em>.{' '}
              {sec.selfHit !== null ? (
                <>
                  With t ≥ 0 it counts as a hit at t = {fmt(sec.selfHit)}: the point would be in its own
                  shadow. With t &gt; t<sub>min</sub>:{' '}
                  {sec.hitWithTMin === null ? 'no hit, the point is lit' : `a hit at ${fmt(sec.hitWithTMin)}`}
                  .
                </>
              ) : (
                'Here rounding happened to put p just outside, so t ≥ 0 already rejects it; on other points it does not.'
              )}
            </p>
          ) : null}
          <TMinSurvey cx={cx} cy={cy} cz={cz} r={model.input.r} method={res.method} />
        </li>
      </ol>
    </div>
  );
});

/**
 * Secondary rays from points spread over the sphere: how many hit their own surface with t ≥ 0
 * and with t > t_min. The paragraph shows the counts once all rays are cast (view/useSurvey).
 */
const TMinSurvey = memo(function TMinSurvey({
  cx,
  cy,
  cz,
  r,
  method,
}: {
  cx: number;
  cy: number;
  cz: number;
  r: number;
  method: RaySphereMethod;
}) {
  const survey = useSurvey(cx, cy, cz, r, method);
  if (!survey) {
    return (
      <p data-testid="tmin-survey" aria-busy="true">
        Casting a ray from each of {SURVEY_POINTS} points spread evenly over this sphere…
      </p>
    );
  }
  return (
    <p
      data-testid="tmin-survey"
      data-zero={survey.withZero}
      data-tmin={survey.withTMin}
      data-count={survey.count}
    >
      Over {survey.count} points spread evenly over this sphere (each computed as C + r n in doubles), a ray
      leaving along the normal hits its own surface with t ≥ 0 at <strong>{survey.withZero}</strong> points,
      and with t &gt; t<sub>min</sub> at <strong>{survey.withTMin}</strong>.
    </p>
  );
});
