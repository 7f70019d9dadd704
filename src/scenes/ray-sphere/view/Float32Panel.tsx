/**
 * The float32 side of the precision views: the `precision` switch's options, the note under the
 * readouts in float32, and the table of errors of both methods in float64 and in float32 side by
 * side (each against the double-double reference of its own inputs).
 */
import type { ReactNode } from 'react';
import type { RaySphereHit } from '../../../core/geometry';
import { errorInUlpsF32 } from '../../../core/geometry';
import type { MethodRow } from '../methodRow';
import type { RaySphereModel } from '../model';
import type { Precision } from '../precisionF32';
import { ScrollTable } from './Precision';

export const PRECISION_OPTIONS: { value: Precision; label: string }[] = [
  { value: 'f64', label: 'float64 (double, as JavaScript)' },
  { value: 'f32', label: 'float32 (single, as a GPU shader)' },
];

const fr = Math.fround;

/** b² − 4ac of the shown a, b, c, evaluated in the model's arithmetic (each step rounded in f32). */
export function textbookDiscriminant(res: RaySphereHit, precision: Precision): number {
  if (precision === 'f32') return fr(fr(res.b * res.b) - fr(fr(4 * res.a) * res.c));
  return res.b * res.b - 4 * res.a * res.c;
}

/** Under the readouts in float32: what was rounded and what the reference is. */
export function Float32Note({ model }: { model: RaySphereModel }) {
  const f = model.f32;
  if (!f) return null;
  return (
    <p className="rs-small" data-testid="precision-note" data-value="f32">
      <strong>float32:</strong> every readout is computed in IEEE single precision (24-bit significands, u₃₂ =
      2⁻²⁴ ≈ 6·10⁻⁸), each operation rounded, as a GPU shader computes it.{' '}
      {f.inputsRounded
        ? 'The typed numbers were first rounded to the nearest float32 (as a shader receives them); '
        : 'The typed numbers are float32 values already; '}
      “exact” below means the exact answer for those float32 inputs.
    </p>
  );
}

const KEYS = ['disc', 't0', 't1', 'hit'] as const;
type Key = (typeof KEYS)[number];

function errOf(row: MethodRow, k: Key): number | null {
  return k === 'disc' ? row.errDisc : k === 't0' ? row.errT0 : k === 't1' ? row.errT1 : row.errHit;
}

function valOf(res: RaySphereHit, k: Key): number | null {
  return k === 'disc' ? res.discriminant : k === 't0' ? res.t0 : k === 't1' ? res.t1 : res.tHit;
}

function cls(e: number | null, u: number): string {
  if (e === null) return 'na';
  if (!Number.isFinite(e) || e > 1e-3) return 'bad';
  return e <= 16 * u ? 'good' : 'meh';
}

function text(e: number | null): string {
  if (e === null) return '—';
  if (e === Infinity) return 'lost / invented';
  if (e === 0) return 'exact';
  return e.toExponential(1);
}

/**
 * Relative errors of the textbook and robust forms in float64 and in float32 against the
 * double-double reference (of the double inputs, and of the float32 inputs), with the float32
 * roots' errors also in float32 ulps.
 */
export function PrecisionCompare({ model }: { model: RaySphereModel }) {
  const f = model.f32;
  if (!model.reference || model.rows.length < 2 || !f || f.rows.length < 2 || !f.reference) {
    return f?.fatal ? (
      <p className="rs-small" data-testid="f32-fatal">
        float32: {f.fatal}
      </p>
    ) : null;
  }
  const pick = (rows: MethodRow[], m: 'naive' | 'stable') => rows.find((r) => r.method === m)!;
  const cols = [
    { id: 'f64-naive', row: pick(model.rows, 'naive'), u: 2 ** -53, ref: model.reference },
    { id: 'f64-stable', row: pick(model.rows, 'stable'), u: 2 ** -53, ref: model.reference },
    { id: 'f32-naive', row: pick(f.rows, 'naive'), u: 2 ** -24, ref: f.reference },
    { id: 'f32-stable', row: pick(f.rows, 'stable'), u: 2 ** -24, ref: f.reference },
  ];
  const labels: Record<Key, ReactNode> = {
    disc: 'Δ',
    t0: 't₀',
    t1: 't₁',
    hit: (
      <>
        t<sub>hit</sub>
      </>
    ),
  };
  return (
    <ScrollTable label="Errors in float64 and float32 side by side">
      <table className="rs-precision rs-compare" data-testid="precision-compare">
        <caption className="rs-small">
          Relative error against the double-double reference, float64 beside float32
          {model.precision === 'f32' ? ' (the readouts above use float32)' : ''}. The float32 roots’ errors
          are also given in float32 ulps.
        </caption>
        <thead>
          <tr>
            <th scope="col"></th>
            <th scope="col">Textbook, float64</th>
            <th scope="col">Robust, float64</th>
            <th scope="col">Textbook, float32</th>
            <th scope="col">Robust, float32</th>
          </tr>
        </thead>
        <tbody>
          {KEYS.map((k) => (
            <tr key={k}>
              <th scope="row">{labels[k]}</th>
              {cols.map((c) => {
                const e = errOf(c.row, k);
                const f32col = c.id.startsWith('f32');
                const refV = k === 'disc' ? null : valOf(c.ref as unknown as RaySphereHit, k);
                const ulps = f32col && k !== 'disc' ? errorInUlpsF32(valOf(c.row.res, k), refV) : null;
                return (
                  <td key={c.id}>
                    <span
                      className={`rs-err ${cls(e, c.u)}`}
                      data-testid={`err-${c.id}-${k}`}
                      data-value={e === null ? 'none' : String(e)}
                    >
                      {text(e)}
                    </span>
                    {ulps !== null && Number.isFinite(ulps) && e !== 0 && e !== null ? (
                      <span className="rs-err" data-testid={`ulps-${c.id}-${k}`} data-value={String(ulps)}>
                        {ulps < 1e6 ? `${ulps.toPrecision(2)} ulp` : '≫ 10⁶ ulp'}
                      </span>
                    ) : null}
                  </td>
                );
              })}
            </tr>
          ))}
          <tr>
            <th scope="row">case</th>
            {cols.map((c) => (
              <td
                key={c.id}
                className={c.row.caseRight ? '' : 'rs-wrong'}
                data-testid={`case-${c.id}`}
                data-value={c.row.res.case}
              >
                {c.row.res.case}
                {c.row.caseRight ? '' : ' ✗ wrong'}
              </td>
            ))}
          </tr>
        </tbody>
      </table>
    </ScrollTable>
  );
}
