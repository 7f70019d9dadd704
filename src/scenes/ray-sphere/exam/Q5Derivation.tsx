/**
 * Q5's written derivation with the numbers of the current ray: substitute, expand, the
 * coefficients, the roots, the two conditions the key marks (Δ ≥ 0, t ≥ 0), the hit, and, folded,
 * why a renderer tests t > t_min (./Q5TMin).
 */
import { memo } from 'react';
import { Derivation, MathTex } from '../../../ui';
import { Fold } from '../../../ui/Fold';
import { activeRows, type RaySphereModel } from '../model';
import { fmt, tx, txVec as v, yes } from '../view/format';
import { TMinNote } from './Q5TMin';

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
          <Fold
            name="tmin"
            summary={
              <>
                Why renderers test t &gt; t<sub>min</sub> instead of t ≥ 0: shadow acne, on this sphere
              </>
            }
          >
            <TMinNote model={model} />
          </Fold>
        </li>
      </ol>
    </div>
  );
});
