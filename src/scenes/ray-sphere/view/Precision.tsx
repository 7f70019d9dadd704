/**
 * The precision views: textbook vs robust vs double-double reference (table), the rendered image
 * of a distant sphere by each method, and the error against distance.
 */
import { useEffect, useMemo, useRef, type ReactNode, type RefObject } from 'react';
import { Plot, ShowAsTable, useSeenOnce, type PlotLayout, type PlotTrace } from '../../../ui';
import { useLogDistance } from './useLogDistance';
import { IMAGE_BG, IMAGE_FG, IMAGE_HOLE } from './imageColours';
import { ERROR_FLOOR, errorVsDistance, type ErrorSeries } from '../errorSeries';
import { renderDistant, shadeImage } from '../distantImage';
import { type RaySphereModel } from '../model';
import { f32ErrorSeries, f32ErrorTraces } from './float32Traces';
import { ERROR_COLOURS, guide, methodCurves } from './errorCurves';
import { describeErrorPlot } from './describe';
import { formatNumber } from '../../../ui/Readout';

function fmtErr(e: number | null): { text: string; cls: string } {
  if (e === null) return { text: '—', cls: 'na' };
  if (e === Infinity) return { text: 'lost / invented', cls: 'bad' };
  if (e === 0) return { text: 'exact', cls: 'good' };
  const cls = e < 1e-13 ? 'good' : e < 1e-8 ? 'meh' : 'bad';
  return { text: e.toExponential(1), cls };
}

const num = (x: number | null) => (x === null ? 'none' : String(x));

/** The table's rows: the quantity, its test id, and where the value and its error are. */
const QUANTITIES = [
  { label: 'Δ = b² − 4ac', id: 'disc', value: 'discriminant', err: 'errDisc' },
  { label: 't₀', id: 't0', value: 't0', err: 'errT0' },
  { label: 't₁', id: 't1', value: 't1', err: 'errT1' },
  {
    label: (
      <>
        t<sub>hit</sub>
      </>
    ),
    id: 'hit',
    value: 'tHit',
    err: 'errHit',
  },
] as const;

/** A table that scrolls sideways on narrow screens, focusable so the keyboard can scroll it. */
export function ScrollTable({ label, children }: { label: string; children: ReactNode }) {
  return (
    <div
      className="rs-table-wrap"
      tabIndex={0}
      role="group"
      aria-label={`${label} (the table scrolls sideways on narrow screens)`}
    >
      {children}
    </div>
  );
}

/** Side-by-side table of both methods against the reference. */
export function PrecisionTable({ model }: { model: RaySphereModel }) {
  const ref = model.reference;
  if (!ref || model.rows.length < 2) return null;
  const [naive, stable] = [
    model.rows.find((r) => r.method === 'naive')!,
    model.rows.find((r) => r.method === 'stable')!,
  ];
  const rows = QUANTITIES.map((q) => ({
    ...q,
    n: num(naive.res[q.value]),
    s: num(stable.res[q.value]),
    ref: num(ref[q.value]),
    en: naive[q.err],
    es: stable[q.err],
  }));
  const cell = (v: string, e: number | null, testId: string, refV: string) => {
    const f = fmtErr(e);
    const abs =
      v !== 'none' && refV !== 'none' && e !== null && e !== 0 && Number.isFinite(e)
        ? Math.abs(Number(v) - Number(refV))
        : null;
    return (
      <td>
        <span className="mono" data-testid={testId} data-value={v}>
          {v}
        </span>
        <span className={`rs-err ${f.cls}`}>
          {f.text === '—' ? '' : `rel. error ${f.text}`}
          {abs !== null && !testId.endsWith('disc') ? ` (off by ${abs.toPrecision(2)})` : ''}
        </span>
      </td>
    );
  };
  return (
    <ScrollTable label="Precision of the two methods">
      <table className="rs-precision" data-testid="precision-table">
        <thead>
          <tr>
            <th scope="col"></th>
            <th scope="col">Textbook (−b&nbsp;±&nbsp;√Δ) / 2a</th>
            <th scope="col">Robust (RTG ch. 7)</th>
            <th scope="col">Reference (double-double)</th>
          </tr>
        </thead>
        <tbody>
          {rows.map((r) => (
            <tr key={r.id}>
              <th scope="row">{r.label}</th>
              {cell(r.n, r.en, `naive-${r.id}`, r.ref)}
              {cell(r.s, r.es, `stable-${r.id}`, r.ref)}
              <td>
                <span className="mono" data-testid={`ref-${r.id}`} data-value={r.ref}>
                  {r.ref}
                </span>
              </td>
            </tr>
          ))}
          <tr>
            <th scope="row">case</th>
            {[naive, stable].map((row) => (
              <td
                key={row.method}
                className={row.caseRight ? '' : 'rs-wrong'}
                data-testid={`${row.method}-case`}
                data-value={row.res.case}
              >
                {row.res.case}
                {row.caseRight ? '' : ' ✗ wrong'}
              </td>
            ))}
            <td data-testid="ref-case" data-value={ref.case}>
              {ref.case}
            </td>
          </tr>
        </tbody>
      </table>
    </ScrollTable>
  );
}

const IMG = 96;

/** One method's render of the distant sphere, with its count of pixels hit (undefined: not yet). */
function MethodImage({
  canvasRef,
  name,
  id,
  hits,
  says,
}: {
  canvasRef: RefObject<HTMLCanvasElement | null>;
  name: string;
  id: string;
  hits: number | undefined;
  /** What the image shows, in numbers (its accessible name after its own). */
  says: string;
}) {
  return (
    <figure>
      <canvas
        ref={canvasRef}
        width={IMG}
        height={IMG}
        className="rs-canvas"
        role="img"
        aria-label={`${name} render of the distant sphere: ${hits === undefined ? 'not yet computed' : `${hits} of ${IMG * IMG} pixels hit; ${says}`}`}
        data-testid={`img-${id}`}
        data-hits={hits}
      />
      <figcaption>
        {name}: {hits ?? '…'} px hit
      </figcaption>
    </figure>
  );
}

/** Two small renders of a distant sphere, one ray per pixel, one per method. */
export function DistantImages() {
  const { dist, slider } = useLogDistance(7.5, {
    label: 'Distance to the sphere, log₁₀(|o\u00a0−\u00a0c|\u00a0/\u00a0r)',
    max: 10,
    testId: 'distant-exp',
  });
  // computed once the panel comes near the screen (it is under "explore further")
  const box = useRef<HTMLDivElement>(null);
  const seen = useSeenOnce(box);
  const img = useMemo(
    () => (seen ? renderDistant(dist, IMG, IMG, () => performance.now()) : null),
    [dist, seen],
  );
  const naiveRef = useRef<HTMLCanvasElement>(null);
  const stableRef = useRef<HTMLCanvasElement>(null);
  useEffect(() => {
    if (!img) return;
    const draw = (cv: HTMLCanvasElement | null, t: Float64Array, other: Float64Array | null) => {
      const g = cv?.getContext('2d');
      if (!g) return;
      const data = g.createImageData(IMG, IMG);
      shadeImage(t, other, 1, data.data, IMAGE_BG, IMAGE_FG, IMAGE_HOLE);
      g.putImageData(data, 0, 0);
    };
    draw(naiveRef.current, img.naive, img.stable);
    draw(stableRef.current, img.stable, null);
  }, [img]);
  return (
    <div className="rs-distant" ref={box}>
      {slider}
      <div className="rs-images">
        <MethodImage
          canvasRef={naiveRef}
          name="Textbook"
          id="naive"
          hits={img?.naiveHits}
          says={img ? `${img.disagree} pixels differ from the robust render` : ''}
        />
        <MethodImage
          canvasRef={stableRef}
          name="Robust"
          id="stable"
          hits={img?.stableHits}
          says="the correct disc"
        />
      </div>
      {img ? (
        <p className="rs-small" data-testid="distant-summary" data-disagree={img.disagree}>
          Sphere {dist.toPrecision(2)} radii away, {IMG}×{IMG} rays per method. The methods disagree on{' '}
          <strong>{img.disagree}</strong> pixels
          {img.disagree ? (
            <>
              {' '}
              (<span className="rs-hole">pink</span>: the textbook form misses where the exact answer hits;
              grey specks outside the disc are hits it invents)
            </>
          ) : null}
          . Both images ({2 * IMG * IMG} rays) were computed on the main thread by the batched kernel in{' '}
          <span data-testid="distant-ms">{img.ms.toFixed(1)} ms</span> (the first render includes the
          JavaScript engine’s warm-up; later ones take about a millisecond).
        </p>
      ) : (
        <p className="rs-small" data-testid="distant-summary">
          Sphere {dist.toPrecision(2)} radii away, {IMG}×{IMG} rays per method: computed when this panel comes
          into view.
        </p>
      )}
    </div>
  );
}

/** Height of the error plot (px): 440 for the axes, the rest for the legend's rows below them. */
const ERROR_PLOT_HEIGHT = 600;

/** The error of each method against distance, with the current configuration marked. */
export function ErrorVsDistance({
  current,
  here,
}: {
  current: number;
  here?: { naive: number | null; stable: number | null };
}) {
  // computed once the plot comes near the screen (it is under "explore further")
  const box = useRef<HTMLDivElement>(null);
  const seen = useSeenOnce(box);
  const s = useMemo(() => (seen ? errorVsDistance() : null), [seen]);
  const e32 = useMemo(() => (s ? f32ErrorSeries(s.dist) : null), [s]);
  const s32 = useMemo(() => (e32 ? f32ErrorTraces(e32) : []), [e32]);
  const u = ERROR_FLOOR;
  const data = useMemo<PlotTrace[]>(
    () =>
      !s
        ? []
        : [
            ...methodCurves(s, ERROR_COLOURS),
            guide(s, (D) => u * D * D, 'u (D/r)²', ERROR_COLOURS.guide),
            guide(s, (D) => u * D, 'u (D/r)', ERROR_COLOURS.guide2),
            ...s32,
            ...(here && current > 1 && Number.isFinite(current)
              ? [
                  {
                    x: [current, current],
                    y: [here.naive, here.stable].map((e) =>
                      e === null || !Number.isFinite(e) ? 1 : Math.min(1, Math.max(u, e)),
                    ),
                    name: 'this ray (Δ)',
                    mode: 'markers' as const,
                    marker: {
                      size: 12,
                      symbol: 'x' as const,
                      color: [ERROR_COLOURS.naive, ERROR_COLOURS.stable],
                      line: { width: 1, color: 'var(--fg)' },
                    },
                  },
                ]
              : []),
          ],
    [s, s32, u, current, here],
  );
  const layout = useMemo(
    (): PlotLayout => ({
      xaxis: { type: 'log', title: { text: 'distance |o − C| / r' }, exponentformat: 'power' },
      yaxis: {
        type: 'log',
        title: { text: 'relative error (median)' },
        exponentformat: 'power',
        range: [-17, 0.3],
      },
      // below the plot, in rows (eleven entries with the float32 curves would cover the curves
      // inside it); the extra height is the legend's, so the axes keep theirs in classroom mode
      legend: { orientation: 'h', x: 0, y: -0.2, xanchor: 'left', yanchor: 'top', bgcolor: 'rgba(0,0,0,0)' },
      margin: { l: 72, r: 12, t: 12, b: 60 },
      shapes:
        current > 1 && Number.isFinite(current)
          ? [
              {
                type: 'line',
                x0: current,
                x1: current,
                yref: 'paper',
                y0: 0,
                y1: 1,
                line: { color: ERROR_COLOURS.guide2, width: 1 },
              },
            ]
          : [],
    }),
    [current],
  );
  return (
    <div ref={box} style={{ minHeight: ERROR_PLOT_HEIGHT }}>
      {s ? (
        <Plot
          data={data}
          layout={layout}
          height={ERROR_PLOT_HEIGHT}
          label="Relative error of Δ and of the hit's t against distance, textbook and robust"
          description={describeErrorPlot(s, e32 ?? undefined)}
          testId="error-plot"
        />
      ) : (
        <div data-testid="error-plot" style={{ height: ERROR_PLOT_HEIGHT }} aria-busy="true" />
      )}
      {s ? <ErrorTables s={s} e32={e32} /> : null}
    </div>
  );
}

/** The error plot's data as tables: float64, and float32 (its own distances, up to 10⁹ r). */
function ErrorTables({ s, e32 }: { s: ErrorSeries; e32: ErrorSeries | null }) {
  const cols = ['D / r', 'textbook Δ', 'robust Δ', 'textbook tₕᵢₜ', 'robust tₕᵢₜ'];
  const rows = (e: ErrorSeries) =>
    e.dist.map((D, i) => [D, e.discNaive[i], e.discStable[i], e.hitNaive[i], e.hitStable[i]]);
  const tables = [
    { e: s, arithmetic: 'float64', id: 'error-table', summary: undefined },
    { e: e32, arithmetic: 'float32', id: 'error-table-f32', summary: 'Show the float32 curves as a table' },
  ];
  return (
    <>
      {tables.map(({ e, arithmetic, id, summary }) =>
        e ? (
          <ShowAsTable
            key={id}
            caption={`Median relative error against distance, ${arithmetic}`}
            columns={cols}
            rows={rows(e)}
            format={fmtTable}
            summary={summary}
            testId={id}
          />
        ) : null,
      )}
    </>
  );
}

const fmtTable = (v: number) => formatNumber(v, 2);
