/**
 * The plots of one draw: the θ and φ histograms against the lobe's marginal densities (their
 * audio traces and tables apart, for a fold), and the 2D histogram over (cos θ, φ) bins of equal solid angle against the integrated density (the χ²
 * test's expected counts), with their standardized difference (O − E)/√E.
 */
import { useMemo } from 'react';
import { AudioTrace, Plot, ShowAsTable, type PlotTrace, type TraceEvent } from '../../../ui';
import { HALF_PI, TWO_PI } from '../../../core/sampling';
import { titled } from './plotTitle';
import type { DrawStats } from '../drawStats';
import type { Lobe } from '../lobe';
import { marginalShape } from '../marginals';
import { chi2Bin, describeChi2Bins, describeMarginal } from './describe';
import { BAR_OPACITY, MODEL, SAMPLED } from './plotColors';

function histTraces(h: MarginalHist, name: string): PlotTrace[] {
  return [
    {
      type: 'bar',
      x: Array.from(h.centers),
      y: Array.from(h.density),
      width: h.width,
      name: `samples`,
      marker: { color: SAMPLED },
      opacity: BAR_OPACITY,
    },
    modelCurve(h.curveX, h.curveY, `p(${name})`),
  ];
}

type MarginalHist = NonNullable<DrawStats['hist']>['theta'];

/** The model's curve (a density or a CDF) beside the samples: one colour and width in every plot. */
export function modelCurve(x: ArrayLike<number>, y: ArrayLike<number>, name: string): PlotTrace {
  return {
    type: 'scatter',
    mode: 'lines',
    x: Array.from(x),
    y: Array.from(y),
    name,
    line: { color: MODEL, width: 2.5 },
  };
}

/** A tick where the density has an interior peak (a horizontal tangent), for the audio trace. */
function peakEvents(f: (x: number) => number, lo: number, hi: number, v: string): TraceEvent[] {
  const s = marginalShape(f, lo, hi);
  const span = hi - lo;
  return !s.flat && s.peak > lo + 0.01 * span && s.peak < hi - 0.01 * span
    ? [{ x: s.peak, kind: 'tangent', label: `peak of p(${v})` }]
    : [];
}

/** One marginal: the histogram against p, and its description. */
function MarginalPlot({
  h,
  v,
  n,
  pdf,
  hi,
  testId,
}: {
  h: MarginalHist;
  v: 'θ' | 'φ';
  n: number;
  pdf: (x: number) => number;
  hi: number;
  testId: string;
}) {
  const traces = useMemo(() => histTraces(h, v), [h, v]);
  const description = useMemo(() => describeMarginal(h, v, n, pdf), [h, v, n, pdf]);
  const name = v === 'θ' ? 'polar angles θ' : 'azimuths φ';
  return (
    <div className="hemi-marginal">
      <Plot
        label={`Histogram of the sampled ${name} against the marginal density p(${v})`}
        description={description}
        data={traces}
        layout={{
          ...titled(`${v}: histogram vs p(${v})`),
          xaxis: { title: { text: `${v} (rad)` }, range: [0, hi] },
          yaxis: { title: { text: 'density' } },
          bargap: 0,
        }}
        testId={testId}
      />
    </div>
  );
}

/** One marginal heard (its audio trace, a tick at a density's interior peak) and read as a table. */
function MarginalSound({
  h,
  v,
  pdf,
  hi,
  testId,
}: {
  h: MarginalHist;
  v: 'θ' | 'φ';
  pdf: (x: number) => number;
  hi: number;
  testId: string;
}) {
  const events = useMemo(() => peakEvents(pdf, 0, hi, v), [pdf, hi, v]);
  const rows = useMemo(() => Array.from(h.centers, (c, b) => [c, h.density[b], pdf(c)]), [h, pdf]);
  return (
    <div className="hemi-marginal">
      <AudioTrace
        label={`histogram of ${v}`}
        xs={h.centers}
        ys={h.density}
        xLabel={v}
        yLabel="density"
        events={events}
        testId={`${testId}-audio`}
      />
      <ShowAsTable
        caption={`Histogram of ${v}: density of the samples in each bin and p(${v}) at its centre`}
        columns={[`${v} (bin centre, rad)`, 'samples (density)', `p(${v})`]}
        rows={rows}
        testId={`${testId}-table`}
      />
    </div>
  );
}

export function MarginalPlots({ stats, lobe }: { stats: DrawStats; lobe: Lobe }) {
  const hist = stats.hist;
  if (!hist) return null;
  return (
    <div className="hemi-plot-grid">
      <MarginalPlot h={hist.theta} v="θ" n={stats.n} pdf={lobe.thetaPdf} hi={HALF_PI} testId="plot-theta" />
      <MarginalPlot h={hist.phi} v="φ" n={stats.n} pdf={lobe.phiPdf} hi={TWO_PI} testId="plot-phi" />
    </div>
  );
}

/** Both marginals heard and tabled (the content of a fold under the histograms). */
export function MarginalData({ stats, lobe }: { stats: DrawStats; lobe: Lobe }) {
  const hist = stats.hist;
  if (!hist) return null;
  return (
    <div className="hemi-plot-grid">
      <MarginalSound h={hist.theta} v="θ" pdf={lobe.thetaPdf} hi={HALF_PI} testId="plot-theta" />
      <MarginalSound h={hist.phi} v="φ" pdf={lobe.phiPdf} hi={TWO_PI} testId="plot-phi" />
    </div>
  );
}

export function Histogram2D({ stats }: { stats: DrawStats }) {
  const chi2 = stats.chi2;
  const data = useMemo(() => {
    if (!chi2) return null;
    const nc = chi2.cosThetaBins;
    const np = chi2.phiBins;
    const x = Array.from({ length: np }, (_, i) => ((i + 0.5) * TWO_PI) / np);
    const y = Array.from({ length: nc }, (_, i) => (i + 0.5) / nc);
    const rows = (f: (k: number) => number) =>
      Array.from({ length: nc }, (_, i) => Array.from({ length: np }, (_, j) => f(i * np + j)));
    const obs = rows((k) => chi2.observed[k]);
    const exp = rows((k) => chi2.expected[k]);
    const diff = rows((k) => chi2Bin(chi2, k).z);
    let zmax = 0;
    for (let k = 0; k < nc * np; k++) zmax = Math.max(zmax, chi2.observed[k], chi2.expected[k]);
    const table = Array.from({ length: nc * np }, (_, k) => {
      const b = chi2Bin(chi2, k);
      return [b.cosTheta, b.phi, b.o, b.e, b.z];
    });
    return { x, y, obs, exp, diff, zmax, table, description: describeChi2Bins(chi2) };
  }, [chi2]);
  if (!data) return null;
  const axes = { xaxis: { title: { text: 'φ' } }, yaxis: { title: { text: 'cos θ' } } };
  const heat = (z: number[][], title: string, label: string, diverging = false) => (
    <Plot
      label={label}
      description={data.description}
      height={240}
      data={[
        {
          type: 'heatmap',
          x: data.x,
          y: data.y,
          z,
          zmin: diverging ? -4 : 0,
          zmax: diverging ? 4 : data.zmax,
          colorscale: diverging ? 'RdBu' : 'Viridis',
          ...(diverging ? { reversescale: true } : {}),
          showscale: diverging,
        },
      ]}
      layout={{ ...titled(title), ...axes }}
    />
  );
  return (
    <>
      <div className="hemi-plot-grid three">
        {heat(data.obs, 'observed', 'Observed counts in bins of equal solid angle')}
        {heat(data.exp, 'expected N∫p dω', 'Expected counts: the density integrated over each bin')}
        {heat(
          data.diff,
          '(O − E)/√E',
          'Standardized difference (observed minus expected) over the square root of expected',
          true,
        )}
      </div>
      <ShowAsTable
        caption="The χ² bins: centre (cos θ, φ), observed and expected counts, (O − E)/√E"
        columns={['cos θ', 'φ (rad)', 'observed', 'expected', '(O − E)/√E']}
        rows={data.table}
        testId="chi2-table"
      />
    </>
  );
}
