/**
 * Q5's live answer (the readouts of the ray at the coarse position, and what they mean) and the
 * note on what the key prints.
 */
import { KeyNote, LiveAnswer, Notice, Readout } from '../../../ui';
import { activeRows } from '../model';
import { sweepAt, type Sweep } from '../sweep';
import { Float32Note, textbookDiscriminant } from '../view/Float32Panel';
import type { RaySphereParams } from '../params';
import { fmt, sweepCoord } from '../view/format';
import { useCoarseModel, type LiveProps } from '../view/Live';

export interface Q5AnswerProps extends LiveProps {
  sweep: Sweep;
  method: RaySphereParams['method'];
}

export function Q5Answer(props: Q5AnswerProps) {
  return (
    <>
      <LiveAnswer testId="live-answer">
        <LiveAnswerBody {...props} />
      </LiveAnswer>
      <KeyNote testId="q5-keynote">
        the key prints no derivation; it refers to <em>Ray Tracing in One Weekend</em> and awards 2 marks for
        Δ ≥ 0 and 2 for t ≥ 0. That book (and this page) call the centre <b>C</b> and the quadratic’s constant
        term c; later editions simplify with b = 2h, h = d·(o&nbsp;−&nbsp;C), giving t =
        (−h&nbsp;±&nbsp;√(h²&nbsp;−&nbsp;ac)) / a: the same roots.
      </KeyNote>
    </>
  );
}

/** What the readouts mean for this method, and how far the robust Δ is from b² − 4ac. */
function methodNote(
  method: RaySphereParams['method'],
  discriminant: number | null,
  discFromAbc: number | null,
  robustDiffers: boolean,
  arithmetic: string,
): string {
  if (method === 'naive') {
    return (
      'All of a, b, c, Δ and the roots are computed the textbook way: Δ is exactly b² − 4ac of the ' +
      `numbers shown (in ${arithmetic} arithmetic).`
    );
  }
  const intro =
    'a, b, c are the textbook coefficients; Δ and the roots come from the robust form 4a(r²\u00a0−\u00a0|ℓ|²), ' +
    'where ℓ = f − (f·d\u00a0/\u00a0d·d) d, f = o − C, runs from the centre to the nearest point of the ray’s line';
  if (!robustDiffers || discFromAbc === null || discriminant === null) {
    return `${intro}. Here it equals b² − 4ac of the a, b, c shown, to the last bit.`;
  }
  const diff = Math.abs(discriminant - discFromAbc);
  const rel = discriminant !== 0 ? ` (relative ${fmt(diff / Math.abs(discriminant))})` : '';
  return (
    `${intro}, which computes the same quantity without cancellation. Here it differs from b² − 4ac of ` +
    `the a, b, c shown (next readout) by ${fmt(diff)}${rel}: rounding in the textbook form.`
  );
}

/**
 * The readouts at the coarse position (the scene does not re-render while the sweep plays: this
 * part re-renders at most RENDER_HZ times a second then, and exactly when paused).
 */
function LiveAnswerBody({ tl, modelAt, sweep, method }: Q5AnswerProps) {
  const { t, model } = useCoarseModel({ tl, modelAt });
  const at = sweepAt(sweep, t);
  const res = model.chosen;
  const active = activeRows(model);
  const f32 = model.precision === 'f32';
  const naiveRow = active.rows.find((x) => x.method === 'naive');
  const discFromAbc = res ? textbookDiscriminant(res, model.precision) : null;
  const robustDiffers =
    method === 'stable' &&
    res !== null &&
    naiveRow !== undefined &&
    naiveRow.res.discriminant !== res.discriminant;
  return (
    <>
      <div className="readouts">
        <Readout id="a" label="a = d·d" value={res?.a ?? null} digits={10} />
        <Readout id="b" label={'b = 2 d·(o\u00a0−\u00a0C)'} value={res?.b ?? null} digits={10} />
        <Readout id="c" label="c = |o − C|² − r²" value={res?.c ?? null} digits={10} />
        <Readout
          id="discriminant"
          label={
            method === 'naive'
              ? 'Δ = b² − 4ac (textbook: from a, b, c as shown)'
              : 'Δ, robust form 4a(r²\u00a0−\u00a0|ℓ|²)'
          }
          value={res?.discriminant ?? null}
          digits={10}
        />
        {method === 'stable' ? (
          <Readout
            id="disc-abc"
            label="b² − 4ac from the a, b, c shown (textbook)"
            value={discFromAbc}
            digits={10}
          />
        ) : null}
        <Readout id="t0" label="t₀" value={res?.t0 ?? null} digits={10} />
        <Readout id="t1" label="t₁" value={res?.t1 ?? null} digits={10} />
        <Readout
          id="t-hit"
          label={
            <>
              t<sub>hit</sub> (nearest t ≥ 0)
            </>
          }
          value={res?.tHit ?? null}
          digits={10}
        />
        <Readout id="case" label="case" value={res?.case ?? null} />
        <Readout
          id="sweep-x"
          label={`${sweepCoord(sweep.mode)} (sweep)`}
          value={Number.isFinite(at.x) ? at.x : null}
          digits={6}
        />
      </div>
      <p className="rs-small" data-testid="disc-method-note">
        {methodNote(
          method,
          res?.discriminant ?? null,
          discFromAbc,
          robustDiffers,
          f32 ? 'float32' : 'double',
        )}
      </p>
      {f32 ? <Float32Note model={model} /> : null}
      {res && active.reference && res.case !== active.reference.case ? (
        <Notice kind="warn" testId="method-wrong">
          The {method === 'naive' ? 'textbook' : 'robust'} form{f32 ? ' in float32' : ''} says{' '}
          <strong>{res.case}</strong>, but the exact answer for these inputs (double-double reference) is{' '}
          <strong>{active.reference.case}</strong>: rounding has changed the case. See the precision table
          under “Explore further”.
        </Notice>
      ) : null}
      {res?.nearTangent && res.case !== 'tangent' ? (
        <p className="rs-small rs-near">
          |Δ| is within this method’s rounding error of 0: the ray is tangent to within{' '}
          {f32 ? 'float32' : 'double'} precision, and whether it hits is decided by the last bits.
        </p>
      ) : null}
    </>
  );
}
