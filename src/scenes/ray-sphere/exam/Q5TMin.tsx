/**
 * Why renderers test t > t_min instead of the exam's t ≥ 0 (folded under the derivation): a
 * secondary ray from the current hit point, and a survey of secondary rays over the whole sphere
 * (cast in short slices once the fold opens, ../view/useSurvey).
 */
import { memo } from 'react';
import { MathTex } from '../../../ui';
import type { RaySphereMethod } from '../../../core/geometry';
import type { RaySphereModel } from '../model';
import { secondaryFromHit, tMinFor } from '../secondaryRay';
import { fmt, txVec as v } from '../view/format';
import { SURVEY_POINTS, useSurvey } from '../view/useSurvey';

/** The note at the current ray and sphere (none when the inputs overflow). */
export const TMinNote = memo(function TMinNote({ model }: { model: RaySphereModel }) {
  const res = model.chosen;
  if (!res) return null;
  const [cx, cy, cz] = model.input.c;
  const sec = secondaryFromHit(model.input, res, res.method);
  const tMin = tMinFor(model.input.r);
  return (
    <>
      <p>
        A shadow or reflection ray starts at a hit point on the surface. That point is computed in floating
        point, so it lies a rounding error inside or outside the sphere, and the quadratic then has a root t ≈
        0 at the starting point itself. With t ≥ 0 that root can count as a hit: the surface shadows itself
        (“shadow acne”, a speckle of dark dots). Testing t &gt; t<sub>min</sub> (a small positive number),
        here t<sub>min</sub> = 10⁻⁴ r = {fmt(tMin)}, skips it.
      </p>
      {sec ? (
        <p data-testid="tmin-example">
          Here: the hit point p = o + t<sub>hit</sub> d = <MathTex tex={v(sec.p)} /> lies |p − C| − r ={' '}
          {fmt(sec.offSurface)} off the surface. A ray leaving it along the outward normal (towards a light
          straight above) has roots t = {fmt(sec.res.t0)} and {fmt(sec.res.t1)}: the first is the far side of
          the sphere behind it, the second is <em>p itself</em>.{' '}
          {sec.selfHit !== null ? (
            <>
              With t ≥ 0 it counts as a hit at t = {fmt(sec.selfHit)}: the point would be in its own shadow.
              With t &gt; t<sub>min</sub>:{' '}
              {sec.hitWithTMin === null ? 'no hit, the point is lit' : `a hit at ${fmt(sec.hitWithTMin)}`}.
            </>
          ) : (
            'Here rounding happened to put p just outside, so t ≥ 0 already rejects it; on other points it does not.'
          )}
        </p>
      ) : null}
      <TMinSurvey cx={cx} cy={cy} cz={cz} r={model.input.r} method={res.method} />
    </>
  );
});

/**
 * Secondary rays from points spread over the sphere: how many hit their own surface with t ≥ 0
 * and with t > t_min. The paragraph shows the counts once all rays are cast (../view/useSurvey).
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
