/**
 * The pixel inspector as text: for the inspected pixel, the primary ray, the sphere's quadratic,
 * the hit, the texture lookup, and the estimator at the hit point (its first samples as a table,
 * its running estimate and standard error against the reference). Every readout carries its full
 * value in `data-value` (vectors as x,y,z; `none` where it does not apply); each group and each
 * sample row links to the exam scene that teaches it.
 */
import type { PixelInspection, SampleRow } from '../../../core/render/inspector';
import type { Vec3 } from '../../../core/vec3';
import { buildScene } from '../../../core/render/scene';
import { formatNumber, formatPlain } from '../../../core/format';
import { Readout } from '../../../ui';
import { raySphereHref, sampleHref, textureHref } from '../links';
import type { RenderModel } from '../model';

/** `data-value` of a vector readout: the components as String(x), comma-separated; none for null. */
export function vectorValue(v: Vec3 | null): string {
  return v ? v.map((x) => String(x)).join(',') : 'none';
}

function VectorReadout({ id, label, value }: { id: string; label: string; value: Vec3 | null }) {
  const dv = vectorValue(value);
  return (
    <div className="readout">
      <span className="readout-label">{label}</span>
      <output className="readout-value" data-testid={id} data-value={dv} title={dv}>
        {value ? `(${value.map((x) => formatNumber(x, 5)).join(', ')})` : '—'}
      </output>
    </div>
  );
}

const cell = (x: number | null) => (x === null ? '—' : formatNumber(x, 4));

function SampleTable({ rows, m, p }: { rows: SampleRow[]; m: RenderModel; p: Vec3 | null }) {
  if (rows.length === 0)
    return <p>The estimator draws no samples here: the ray sees an emitter or nothing.</p>;
  return (
    <div className="render-table-scroll">
      <table className="render-samples" data-testid="pixel-samples">
        <caption>The first {rows.length} samples of the direct-light estimator at p</caption>
        <thead>
          <tr>
            <th scope="col">#</th>
            <th scope="col">technique</th>
            <th scope="col">direction ωᵢ</th>
            <th scope="col">light point</th>
            <th scope="col">f</th>
            <th scope="col">L</th>
            <th scope="col">cos θ</th>
            <th scope="col">cos θₗ</th>
            <th scope="col">r²</th>
            <th scope="col">pdf</th>
            <th scope="col">pdf (solid angle)</th>
            <th scope="col">MIS weight</th>
            <th scope="col">term</th>
            <th scope="col">taught in</th>
          </tr>
        </thead>
        <tbody>
          {rows.map((r, k) => {
            const link = sampleHref(m, r, p);
            return (
              <tr key={k}>
                <td>{k + 1}</td>
                <td>{r.technique}</td>
                <td>{r.direction.map((x) => formatNumber(x, 3)).join(', ')}</td>
                <td>{r.lightPoint ? r.lightPoint.map((x) => formatNumber(x, 3)).join(', ') : '—'}</td>
                <td>{cell(r.f)}</td>
                <td>{cell(r.L)}</td>
                <td>{cell(r.cosTheta)}</td>
                <td>{cell(r.cosThetaL)}</td>
                <td>{cell(r.r2)}</td>
                <td>
                  {cell(r.pdf)} <span className="render-unit">/{r.measure === 'area' ? 'area' : 'sr'}</span>
                </td>
                <td>{cell(r.pdfSolidAngle)}</td>
                <td>{cell(r.weight)}</td>
                <td>{cell(r.term)}</td>
                <td>
                  <a href={link.href}>{link.label}</a>
                </td>
              </tr>
            );
          })}
        </tbody>
      </table>
    </div>
  );
}

export function Inspector({
  m,
  result,
  pending,
}: {
  m: RenderModel;
  result: PixelInspection | undefined;
  pending: boolean;
}) {
  if (!m.px)
    return (
      <p data-testid="pixel-none">
        Click the image, or give <code>px=i,j</code> in the link, to open a pixel.
      </p>
    );
  if (!result)
    return (
      <p role="status" data-testid="pixel-pending">
        {pending ? `Inspecting pixel ${m.px.join(', ')}…` : 'The inspector could not run.'}
      </p>
    );
  const r = result;
  const sphere = buildScene(m.spec).sphere;
  return (
    <div className="render-inspector" data-testid="pixel-inspector">
      <h3>
        Pixel ({r.i}, {r.j}): the ray through its centre
      </h3>
      <div className="readouts">
        <VectorReadout id="pixel-o" label="origin o" value={r.o} />
        <VectorReadout id="pixel-d" label="direction d" value={r.d} />
      </div>
      <h3>
        The sphere’s quadratic (Q5){' '}
        {sphere ? <a href={raySphereHref(sphere, r.o, r.d)}>in the ray–sphere scene</a> : null}
      </h3>
      <div className="readouts">
        <Readout id="pixel-discriminant" label="discriminant" value={r.discriminant} />
        <Readout id="pixel-t" label="t (stable form)" value={r.t} />
        <Readout id="pixel-hit" label="the ray hits" value={r.hit} />
        <VectorReadout id="pixel-p" label="hit point p" value={r.p} />
      </div>
      <h3>
        The texture lookup (Q3){' '}
        {r.u !== null && r.v !== null ? <a href={textureHref(m, r.u, r.v)}>in the texture scene</a> : null}
      </h3>
      <div className="readouts">
        <Readout id="pixel-u" label="u" value={r.u} />
        <Readout id="pixel-v" label="v" value={r.v} />
        <Readout id="pixel-texel" label={`texel (${m.spec.exam.filter})`} value={r.texel} />
        <Readout id="pixel-albedo" label="albedo" value={r.albedo} />
      </div>
      <h3>The radiance leaving p towards the eye (Q1, Q2, Q6)</h3>
      <div className="readouts">
        <Readout id="pixel-estimate" label={`estimate (${m.trace.strategy})`} value={r.estimate} />
        <Readout id="pixel-stderr" label="standard error" value={r.stderr} />
        <Readout id="pixel-n" label="samples n" value={r.n} />
        <Readout
          id="pixel-reference"
          label="reference"
          value={r.reference}
          note={
            r.referenceKind === 'converged'
              ? `± ${formatNumber(r.referenceStderr, 3)} (a long MIS run)`
              : 'closed form'
          }
        />
        <Readout id="pixel-reference-kind" label="reference kind" value={r.referenceKind} />
        {r.tTest ? (
          <>
            <Readout
              id="pixel-ttest-p"
              label={r.referenceKind === 'exact' ? 'Student t-test p' : 'Welch t-test p'}
              value={r.tTest.pValue}
              digits={3}
              note={
                !Number.isFinite(r.tTest.t)
                  ? 'every sample gave the same value, and it differs from the reference'
                  : r.tTest.pValue === 0
                    ? `t = ${formatNumber(r.tTest.t, 4)}; p is below the smallest double, 10⁻³⁰⁸`
                    : `t = ${formatNumber(r.tTest.t, 4)}`
              }
            />
            <Readout
              id="pixel-ttest"
              label={`unbiased at α = ${formatPlain(r.tTest.alpha)}`}
              value={r.tTest.pass ? 'pass' : 'fail'}
            />
          </>
        ) : null}
      </div>
      <p className="render-verdict">
        {r.stderr > 0
          ? `The estimate is ${formatPlain(Math.abs(r.estimate - r.reference) / r.stderr, 3)} standard errors from the reference.`
          : `Every sample returned the same value: the estimate differs from the reference by ${formatNumber(Math.abs(r.estimate - r.reference))}.`}
      </p>
      <SampleTable rows={r.rows} m={m} p={r.p} />
    </div>
  );
}
