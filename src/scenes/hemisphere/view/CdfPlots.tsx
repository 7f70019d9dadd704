/**
 * Q1(c)'s CDFs as curves: P(θ) and P(φ) of the chosen density (integrated from its marginals),
 * the samples' CDF from the histograms of (d) beside them, and the first sample's point (θ₁, ξ₁):
 * the CDF maps each angle back to its uniform number. Each plot is named and summarized; folded
 * under them, each can be heard (its audio trace, a tick at the median) and read as a table.
 */
import { useMemo } from 'react';
import { Fold } from '../../../ui/Fold';
import { AudioTrace, Plot, ShowAsTable, summarizeSeries, type PlotTrace } from '../../../ui';
import { formatSignificant } from '../../../ui/format';
import { HALF_PI, TWO_PI, sphericalPhi, sphericalTheta } from '../../../core/sampling';
import type { DrawStats } from '../drawStats';
import type { Lobe } from '../lobe';
import { cdfCurve, histogramCdf, marginalShape } from '../marginals';
import { titled } from './plotTitle';
import { modelCurve } from './Plots';
import { REFERENCE, SAMPLED } from './plotColors';

const num = (x: number) => formatSignificant(x, 3, 'times');
/** Points per histogram bin on the model's CDF (so the table can read it at the bins' edges). */
const PER_BIN = 16;

type Hist = NonNullable<DrawStats['hist']>['theta'];

/** The model's CDF on a fine grid (PER_BIN points per histogram bin) and the samples' CDF at the bins' edges. */
function useCdf(f: (x: number) => number, hi: number, hist: Hist | null) {
  const bins = hist ? hist.centers.length : 36;
  const model = useMemo(() => cdfCurve(f, 0, hi, bins * PER_BIN), [f, hi, bins]);
  const samples = useMemo(() => (hist ? histogramCdf(hist.density, hist.width, 0) : null), [hist]);
  const median = useMemo(() => marginalShape(f, 0, hi).median, [f, hi]);
  return { bins, model, samples, median };
}

function CdfPlot({
  f,
  hi,
  v,
  hist,
  at,
  testId,
}: {
  f: (x: number) => number;
  hi: number;
  v: 'θ' | 'φ';
  hist: Hist | null;
  /** The first sample: its angle and the uniform number that set it (if this sampler inverts P with it). */
  at: { x: number; xi: number } | null;
  testId: string;
}) {
  const { model, samples, median } = useCdf(f, hi, hist);
  // P at the first sample's angle, read off the curve (linear between its points)
  const pAt = useMemo(() => {
    if (!at) return null;
    const m = model.x.length - 1;
    const q = Math.min(m - 1, Math.max(0, Math.floor((at.x / hi) * m)));
    const f0 = (at.x - model.x[q]) / (model.x[q + 1] - model.x[q]);
    return model.y[q] + f0 * (model.y[q + 1] - model.y[q]);
  }, [at, model, hi]);
  const inverts = at !== null && pAt !== null && Math.abs(pAt - at.xi) < 1e-3;
  const traces = useMemo(() => {
    const out: PlotTrace[] = [modelCurve(model.x, model.y, `P(${v})`)];
    if (samples)
      out.push({
        type: 'scatter',
        mode: 'markers',
        x: Array.from(samples.x),
        y: Array.from(samples.y),
        name: 'samples',
        marker: { color: SAMPLED, size: 5, symbol: 'square' },
      });
    if (at && pAt !== null)
      out.push({
        type: 'scatter',
        mode: 'lines+markers',
        x: [at.x, at.x, 0],
        y: [0, pAt, pAt],
        name: `first sample: P(${v}₁)${inverts ? ' = ξ' : ''}`,
        line: { color: REFERENCE, dash: 'dot', width: 1.5 },
        marker: { size: [0, 9, 0], symbol: 'diamond' },
      });
    return out;
  }, [model, samples, at, pAt, inverts, v]);
  const gap = useMemo(() => {
    if (!samples) return null;
    let d = 0;
    for (let b = 0; b < samples.x.length; b++) d = Math.max(d, Math.abs(samples.y[b] - model.y[b * PER_BIN]));
    return d;
  }, [samples, model]);
  const description = [
    `The CDF P(${v}) of the chosen density, 0 at ${v} = 0 and 1 at ${v} = ${num(hi)} rad.`,
    summarizeSeries(model.x, model.y, { xLabel: `${v} (rad)`, yLabel: `P(${v})`, format: num }),
    `P(${v}) = ½ at ${v} = ${num(median)} rad.`,
    at && pAt !== null
      ? `The first sample's ${v} = ${num(at.x)} rad has P(${v}) = ${num(pAt)}${
          inverts
            ? ', its uniform number: the CDF undoes the inversion.'
            : `, while its uniform number is ${num(at.xi)}: this sampler does not invert P(${v}) with it alone.`
        }`
      : '',
    gap !== null ? `The samples' CDF stays within ${num(gap)} of P(${v}) at the bins' edges.` : '',
  ]
    .filter(Boolean)
    .join(' ');
  return (
    <div className="hemi-marginal">
      <Plot
        label={`The CDF P(${v}) of the chosen density${samples ? ' against the samples' : ''}`}
        description={description}
        data={traces}
        layout={{
          ...titled(`P(${v}): the CDF${samples ? ' vs the samples' : ''}`),
          xaxis: { title: { text: `${v} (rad)` }, range: [0, hi] },
          yaxis: { title: { text: `P(${v}) = ξ` }, range: [0, 1.02] },
        }}
        height={260}
        testId={testId}
      />
    </div>
  );
}

/** The CDF heard (its audio trace, a tick at the median) and read as a table, at the bins' edges. */
function CdfData({
  f,
  hi,
  v,
  hist,
  testId,
}: {
  f: (x: number) => number;
  hi: number;
  v: 'θ' | 'φ';
  hist: Hist | null;
  testId: string;
}) {
  const { bins, model, samples, median } = useCdf(f, hi, hist);
  // heard and tabled at the bins' edges: a few dozen points to step through, not hundreds
  const edges = useMemo(() => {
    const x = new Float64Array(bins + 1);
    const y = new Float64Array(bins + 1);
    for (let b = 0; b <= bins; b++) {
      x[b] = model.x[b * PER_BIN];
      y[b] = model.y[b * PER_BIN];
    }
    return { x, y };
  }, [bins, model]);
  const rows = useMemo(
    () =>
      Array.from({ length: bins + 1 }, (_, b) => {
        const row = [edges.x[b], edges.y[b]];
        return samples ? [...row, samples.y[b]] : row;
      }),
    [bins, edges, samples],
  );
  return (
    <div className="hemi-marginal">
      <AudioTrace
        label={`the CDF P(${v})`}
        xs={edges.x}
        ys={edges.y}
        xLabel={v}
        yLabel={`P(${v})`}
        events={[{ x: median, kind: 'root', label: `P(${v}) = ½, the median` }]}
        testId={`${testId}-audio`}
      />
      <ShowAsTable
        caption={`P(${v}) at the edges of the histogram's bins${samples ? ', and the fraction of samples below each' : ''}`}
        columns={samples ? [`${v} (rad)`, `P(${v})`, 'samples below'] : [`${v} (rad)`, `P(${v})`]}
        rows={rows}
        testId={`${testId}-table`}
      />
    </div>
  );
}

export function CdfPlots({
  lobe,
  stats,
  xi,
}: {
  lobe: Lobe;
  /** The current draw's histograms (null while they are computed). */
  stats: DrawStats | null;
  /** The first sample's uniform numbers (its angles are this lobe's warp of them). */
  xi: { xi1: number; xi2: number } | null;
}) {
  const hist = stats?.hist ?? null;
  const [atTheta, atPhi] = useMemo(() => {
    if (!xi) return [null, null];
    const d = [0, 0, 0];
    lobe.sample(xi.xi1, xi.xi2, d, 0);
    return [
      { x: sphericalTheta(d[0], d[1], d[2]), xi: xi.xi1 },
      { x: sphericalPhi(d[0], d[1]), xi: xi.xi2 },
    ];
  }, [lobe, xi]);
  return (
    <>
      <div className="hemi-plot-grid" data-testid="cdf-plots">
        <CdfPlot
          f={lobe.thetaPdf}
          hi={HALF_PI}
          v="θ"
          hist={hist?.theta ?? null}
          at={atTheta}
          testId="plot-cdf-theta"
        />
        <CdfPlot
          f={lobe.phiPdf}
          hi={TWO_PI}
          v="φ"
          hist={hist?.phi ?? null}
          at={atPhi}
          testId="plot-cdf-phi"
        />
      </div>
      <Fold name="cdf-sound" summary="Hear the CDFs P(θ) and P(φ), or read them as tables">
        <div className="hemi-plot-grid">
          <CdfData f={lobe.thetaPdf} hi={HALF_PI} v="θ" hist={hist?.theta ?? null} testId="plot-cdf-theta" />
          <CdfData f={lobe.phiPdf} hi={TWO_PI} v="φ" hist={hist?.phi ?? null} testId="plot-cdf-phi" />
        </div>
      </Fold>
    </>
  );
}
