/**
 * Plotly views of one draw: the θ and φ histograms against the lobe's marginal densities, and the
 * 2D histogram over (cos θ, φ) bins of equal solid angle against the integrated density (the χ²
 * test's expected counts), with their standardized difference (O − E)/√E.
 */
import { useMemo } from 'react';
import { Plot, type PlotTrace } from '../../../ui';
import { TWO_PI } from '../../../core/sampling';
import { LEGEND_INSIDE, titled } from './plotTitle';
import type { DrawStats } from '../model';

function histTraces(h: NonNullable<DrawStats['hist']>['theta'], name: string): PlotTrace[] {
  return [
    {
      type: 'bar',
      x: Array.from(h.centers),
      y: Array.from(h.density),
      width: h.width,
      name: `samples`,
      marker: { color: 'rgba(70,120,200,0.55)' },
    },
    {
      type: 'scatter',
      mode: 'lines',
      x: Array.from(h.curveX),
      y: Array.from(h.curveY),
      name: `p(${name})`,
      line: { color: '#d0502a', width: 2.5 },
    },
  ];
}

export function MarginalPlots({ stats }: { stats: DrawStats }) {
  const hist = stats.hist;
  const theta = useMemo(() => (hist ? histTraces(hist.theta, 'θ') : []), [hist]);
  const phi = useMemo(() => (hist ? histTraces(hist.phi, 'φ') : []), [hist]);
  if (!hist) return null;
  return (
    <div className="hemi-plot-grid">
      <Plot
        ariaLabel="Histogram of the sampled polar angles θ against the marginal density p(θ)"
        data={theta}
        layout={{
          ...titled('θ: histogram vs p(θ)'),
          xaxis: { title: { text: 'θ (rad)' }, range: [0, Math.PI / 2] },
          yaxis: { title: { text: 'density' } },
          bargap: 0,
          legend: LEGEND_INSIDE,
        }}
        testId="plot-theta"
      />
      <Plot
        ariaLabel="Histogram of the sampled azimuths φ against the marginal density p(φ)"
        data={phi}
        layout={{
          ...titled('φ: histogram vs p(φ)'),
          xaxis: { title: { text: 'φ (rad)' }, range: [0, TWO_PI] },
          yaxis: { title: { text: 'density' } },
          bargap: 0,
          legend: LEGEND_INSIDE,
        }}
        testId="plot-phi"
      />
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
    const diff = rows((k) => {
      const e = chi2.expected[k];
      return e > 0 ? (chi2.observed[k] - e) / Math.sqrt(e) : 0;
    });
    let zmax = 0;
    for (let k = 0; k < nc * np; k++) zmax = Math.max(zmax, chi2.observed[k], chi2.expected[k]);
    return { x, y, obs, exp, diff, zmax };
  }, [chi2]);
  if (!data) return null;
  const axes = { xaxis: { title: { text: 'φ' } }, yaxis: { title: { text: 'cos θ' } } };
  const heat = (z: number[][], title: string, ariaLabel: string, diverging = false) => (
    <Plot
      ariaLabel={ariaLabel}
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
  );
}
