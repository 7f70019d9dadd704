/**
 * Equal time and equal error (core/render/equalTime): every strategy renders the same small image
 * for the same time budget in a worker, and the panel shows what a rendering paper shows: the
 * images side by side with a zoomed inset where they differ most, relMSE against time on log–log
 * axes with the −1 slope every unbiased estimator follows and mean FLIP against time beside it,
 * the ranking at equal time, and the time
 * each strategy needed to reach one error (equal error), read off the same runs.
 */
import { useEffect, useMemo, useRef } from 'react';
import { Notice, Plot, type PlotTrace } from '../../../ui';
import { ScrollBox } from '../../../ui/ScrollBox';
import { readoutValue } from '../../../ui/Readout';
import { summarizeSeries } from '../../../ui/summary';
import { formatNumber, formatPlain } from '../../../core/format';
import { equalErrorTarget, rankByError, timeToError, type StrategyRun } from '../../../core/render/equalTime';
import { useWorkerJob } from '../../../workers';
import { makeRenderWorker } from '../jobs';
import { equalTimeArgs } from '../jobArgs';
import type { RenderModel } from '../model';
import { EQUAL_TIME_BUDGETS, type RenderParams } from '../params';
import { srgbByte } from '../../../core/image/srgb';

/** Side of the zoomed inset, in image pixels, and its magnification. */
const INSET = 16;

/** The 16 × 16 window (on an 8-pixel grid) where the strategies' images differ most from the reference. */
export function insetWindow(
  runs: readonly StrategyRun[],
  reference: Float64Array,
  res: number,
): [number, number] {
  const err = new Float64Array(res * res);
  for (const r of runs)
    for (let k = 0; k < err.length; k++) {
      const d = r.image[k] - reference[k];
      if (Number.isFinite(d)) err[k] += Math.abs(d);
    }
  let best: [number, number] = [0, 0];
  let bestSum = -1;
  for (let y = 0; y + INSET <= res; y += INSET / 2)
    for (let x = 0; x + INSET <= res; x += INSET / 2) {
      let s = 0;
      for (let j = y; j < y + INSET; j++) for (let i = x; i < x + INSET; i++) s += err[j * res + i];
      if (s > bestSum) {
        bestSum = s;
        best = [x, y];
      }
    }
  return best;
}

/** Draws `values` (linear radiance, row-major res × res), or its window at (x0, y0) of side w, into the canvas. */
function drawImage(
  canvas: HTMLCanvasElement | null,
  values: Float64Array,
  res: number,
  x0 = 0,
  y0 = 0,
  w = res,
) {
  const ctx = canvas?.getContext('2d');
  if (!ctx) return;
  const img = ctx.createImageData(w, w);
  for (let j = 0; j < w; j++)
    for (let i = 0; i < w; i++) {
      const b = srgbByte(values[(y0 + j) * res + (x0 + i)]);
      const o = 4 * (j * w + i);
      img.data[o] = img.data[o + 1] = img.data[o + 2] = b;
      img.data[o + 3] = 255;
    }
  ctx.putImageData(img, 0, 0);
}

function RunImage({ run, res, inset }: { run: StrategyRun; res: number; inset: [number, number] }) {
  const full = useRef<HTMLCanvasElement>(null);
  const zoom = useRef<HTMLCanvasElement>(null);
  useEffect(() => {
    drawImage(full.current, run.image, res);
    drawImage(zoom.current, run.image, res, inset[0], inset[1], INSET);
  }, [run, res, inset]);
  return (
    <figure className="et-image" data-testid={`et-image-${run.strategy}`}>
      <canvas
        ref={full}
        width={res}
        height={res}
        role="img"
        aria-label={`${run.strategy}: ${run.spp} samples per pixel, relMSE ${formatNumber(run.relMse, 3)}`}
      />
      <canvas ref={zoom} width={INSET} height={INSET} className="et-inset" aria-hidden="true" />
      <figcaption>
        {run.strategy}
        <br />
        {run.spp} spp
      </figcaption>
    </figure>
  );
}

/**
 * Each strategy's error against render time, log–log: relMSE after every pass, with the slope −1
 * every unbiased estimator's relMSE follows drawn through the median strategy's curve; or mean
 * FLIP where it was measured (passes 1, 2, 4, …, the last), which has no such law.
 */
function errorPlot(runs: readonly StrategyRun[], order: readonly number[], measure: 'relMse' | 'flip') {
  const label = measure === 'relMse' ? 'relMSE' : 'mean FLIP';
  const points = (r: StrategyRun) => {
    const x: number[] = [];
    const y: number[] = [];
    r.curve.ms.forEach((ms, k) => {
      if (Number.isFinite(r.curve[measure][k])) {
        x.push(ms);
        y.push(r.curve[measure][k]);
      }
    });
    return { x, y };
  };
  const data: PlotTrace[] = runs.map((r) => ({
    ...points(r),
    type: 'scatter',
    mode: measure === 'relMse' ? 'lines' : 'lines+markers',
    name: r.strategy,
  }));
  if (measure === 'relMse') {
    // the −1 slope through the middle of the median strategy's curve
    const mid = runs[order[Math.floor(order.length / 2)]];
    const k = Math.floor(mid.curve.ms.length / 2);
    const [x0, y0] = [mid.curve.ms[k], mid.curve.relMse[k]];
    const xs = runs.flatMap((r) => r.curve.ms).filter((x) => x > 0);
    const lo = Math.min(...xs),
      hi = Math.max(...xs);
    data.push({
      x: [lo, hi],
      y: [(y0 * x0) / lo, (y0 * x0) / hi],
      type: 'scatter',
      mode: 'lines',
      name: 'slope −1',
      line: { dash: 'dot', color: 'gray' },
    });
  }
  const words = runs
    .map((r) => {
      const { x, y } = points(r);
      return summarizeSeries(x, y, { xLabel: 'time (ms)', yLabel: `${r.strategy} ${label}`, logLog: true });
    })
    .join(' ');
  return { data, words, label };
}

/** The fold; `et` is the link's budget per strategy (ms), and choosing another writes it there. */
export function EqualTime({
  m,
  et,
  onEt,
}: {
  m: RenderModel;
  et: RenderParams['et'];
  onEt: (et: RenderParams['et']) => void;
}) {
  const budget = Number(et);
  const args = useMemo(() => equalTimeArgs(m, budget), [m, budget]);
  const job = useWorkerJob(makeRenderWorker, 'equalTime', args, { delayMs: 100 });
  const done = job.result;
  const finished = done?.runs.length ?? job.partial?.finished ?? 0;
  const exact = done ? done.exact : null;
  const target = done ? equalErrorTarget(done.runs) : NaN;
  const order = useMemo(() => (done ? rankByError(done.runs) : []), [done]);
  const inset = useMemo(
    () => (done ? insetWindow(done.runs, done.reference, args.res) : ([0, 0] as [number, number])),
    [done, args.res],
  );

  const plot = useMemo(
    () => (done && exact && exact > 0 ? errorPlot(done.runs, order, 'relMse') : null),
    [done, exact, order],
  );
  const flipPlot = useMemo(
    () => (done && exact && exact > 0 ? errorPlot(done.runs, order, 'flip') : null),
    [done, exact, order],
  );

  return (
    <div className="render-equal-time" data-testid="equal-time">
      <p>
        Each strategy renders the same {args.res} × {args.res} image (one sample per pixel per pass) for the
        same time, in a worker, and is measured against the exact reference after every pass. An unbiased
        estimator&apos;s relMSE falls as 1/time: a line of slope −1 on these axes; the better strategy is the
        lower line. Mean FLIP, the perceived difference of the images as shown (8-bit sRGB, about 67 pixels
        per degree), is measured after passes 1, 2, 4, 8, … and the last.
      </p>
      <label className="et-budget">
        Time per strategy{' '}
        <select
          value={et}
          onChange={(e) => onEt(e.currentTarget.value as RenderParams['et'])}
          data-testid="et-budget"
        >
          {EQUAL_TIME_BUDGETS.map((b) => (
            <option key={b} value={b}>
              {Number(b) < 1000 ? `${b} ms` : `${Number(b) / 1000} s`}
            </option>
          ))}
        </select>
      </label>
      <p role="status" data-testid="et-status">
        {job.error
          ? `The comparison stopped: ${job.error.message}`
          : done
            ? `Done: ${done.runs.length} strategies, ${formatPlain(budget)} ms each.`
            : `Rendering… ${finished} of ${args.strategies.length} strategies done.`}
      </p>
      {done && exact === 0 ? (
        <Notice kind="info" testId="et-no-reference">
          No pixel of this view has an exact reference (with more than one bounce, or on Veach&apos;s plates,
          the reference is a converged run), so there is no error to compare. Choose the exam scene or the
          furnace with one bounce.
        </Notice>
      ) : null}
      {done && exact ? (
        <>
          <ScrollBox label="Strategies at equal time and equal error">
            <table className="data-table et-table">
              <caption>
                At equal time ({formatPlain(budget)} ms each), ranked by relMSE; and the time each needed to
                reach the worst of them, relMSE {formatNumber(target, 3)} (equal error)
              </caption>
              <thead>
                <tr>
                  <th scope="col">rank</th>
                  <th scope="col">strategy</th>
                  <th scope="col">samples per pixel</th>
                  <th scope="col">relMSE</th>
                  <th scope="col">mean FLIP</th>
                  <th scope="col">time to relMSE {formatNumber(target, 3)}</th>
                </tr>
              </thead>
              <tbody>
                {order.map((k, rank) => {
                  const r = done.runs[k];
                  const t = timeToError(r, target);
                  return (
                    <tr key={r.strategy}>
                      <td>{rank + 1}</td>
                      <th scope="row">{r.strategy}</th>
                      <td data-testid={`et-spp-${r.strategy}`} data-value={r.spp}>
                        {r.spp}
                      </td>
                      <td data-testid={`et-relmse-${r.strategy}`} data-value={readoutValue(r.relMse)}>
                        {formatNumber(r.relMse, 4)}
                      </td>
                      <td data-testid={`et-flip-${r.strategy}`} data-value={readoutValue(r.flip)}>
                        {formatNumber(r.flip, 3)}
                      </td>
                      <td data-testid={`et-time-${r.strategy}`} data-value={readoutValue(t)}>
                        {t === null ? '—' : `${formatNumber(t, 3)} ms`}
                      </td>
                    </tr>
                  );
                })}
              </tbody>
            </table>
          </ScrollBox>
          <p data-testid="et-ranking" data-value={order.map((k) => done.runs[k].strategy).join(',')}>
            Best to worst at equal time: {order.map((k) => done.runs[k].strategy).join(', ')}.
          </p>
          <div className="et-images">
            {done.runs.map((r) => (
              <RunImage key={r.strategy} run={r} res={args.res} inset={inset} />
            ))}
          </div>
          <p className="small">
            Under each image, ×{Math.round(96 / INSET)} of the {INSET} × {INSET} pixels at ({inset[0]},{' '}
            {inset[1]}) where the images differ most from the reference.
          </p>
          {(
            [
              [plot, 'et-plot'],
              [flipPlot, 'et-flip-plot'],
            ] as const
          ).map(([p, testId]) =>
            p ? (
              <Plot
                key={testId}
                data={p.data}
                label={`${p.label} against render time for each strategy (log–log)`}
                description={p.words}
                testId={testId}
                height={320}
                layout={{
                  xaxis: { type: 'log', title: { text: 'time (ms)' } },
                  yaxis: { type: 'log', title: { text: p.label } },
                  margin: { l: 56, r: 16, t: 24, b: 44 },
                }}
              />
            ) : null,
          )}
        </>
      ) : null}
    </div>
  );
}
