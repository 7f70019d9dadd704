/**
 * The identity as printed on the exam paper (Jacobian upside down), p(θ, φ) = p(ω)/sin θ ∝ cot θ e^φ, and the key's marginal 2 cot θ: why it is not a density.
 * The θ-integral ∫_ε^{π/2} cot θ dθ = −ln sin ε grows without bound as ε → 0; the scene shows the
 * density near θ = 0 and the partial integral, never a normalization constant or samples.
 */
import { useMemo, useState } from 'react';
import { MathTex, Notice, Plot, Slider, Readout, formatNumber } from '../../../ui';
import { LEGEND_INSIDE, titled } from './plotTitle';
import { examLobeK, invertedJacobianDensity, invertedJacobianPartialIntegral } from '../../../core/sampling';
import { invertedJacobianSeries } from '../examChecks';
import { MODEL, SAMPLED } from './plotColors';

export function InvertedJacobian() {
  const [eps, setEps] = useState(1e-3);
  const series = useMemo(() => invertedJacobianSeries(60), []);
  const dens = useMemo(() => {
    const x: number[] = [];
    const y: number[] = [];
    for (let i = 0; i <= 120; i++) {
      const t = 10 ** (-4 + (i / 120) * Math.log10((Math.PI / 2) * 1e4));
      x.push(t);
      y.push((2 * invertedJacobianDensity(t, 0)) / examLobeK()); // the key's p(θ) = 2 cot θ (φ = 0, k factored out)
    }
    return { x, y };
  }, []);
  const partial = invertedJacobianPartialIntegral(eps);
  return (
    <div className="inverted" data-testid="inverted-jacobian">
      <Notice kind="warn" testId="inverted-message">
        Not integrable: with the identity as printed on the exam paper, p(ω) = sin θ p(θ, φ), the change of
        variables gives p(θ, φ) = p(ω)/sin θ = k cot θ e<sup>φ</sup>, and the key&apos;s marginal p(θ) = 2 cot
        θ has ∫₀<sup>π/2</sup> 2 cot θ dθ = ∞ (it diverges at θ → 0). No constant normalizes it, so there is
        no CDF to invert and nothing to sample: the χ² test and the importance estimate are off (their
        readouts say “none”). The key grades this route leniently; the correct identity is p(θ, φ) = sin θ
        p(ω).
      </Notice>
      <MathTex
        display
        tex={`\\int_{\\varepsilon}^{\\pi/2}2\\cot\\theta\\,d\\theta = 2\\Big[\\ln\\sin\\theta\\Big]_{\\varepsilon}^{\\pi/2} = -2\\ln\\sin\\varepsilon \\;\\xrightarrow[\\varepsilon\\to 0]{}\\; \\infty`}
      />
      <p>
        Why it fails: probability is conserved, p(θ, φ) dθ dφ = p(ω) dω, and a small patch of directions has
        solid angle dω = sin θ dθ dφ, so p(θ, φ) = sin θ · p(ω). Dividing instead multiplies the correct
        density by 1/sin²θ, which near the pole behaves like 1/θ² · θ = 1/θ: the classic non-integrable
        singularity. The readout below is ∫ from ε to π/2 of cot θ dθ = −ln sin ε (half the key&apos;s 2 cot θ
        integral): it grows without bound as ε shrinks.
      </p>
      <Slider label="ε (lower limit of θ)" value={eps} min={1e-15} max={1} log onChange={setEps} unit="rad" />
      <Readout
        id="inverted-partial"
        label={`∫ from ε to π/2 of cot θ dθ at ε = ${formatNumber(eps, 3)}`}
        value={partial}
        digits={8}
      />
      <div className="hemi-plot-grid">
        <Plot
          ariaLabel="The key's marginal 2 cot θ near θ = 0, on log axes: it grows like 2/θ"
          data={[
            {
              type: 'scatter',
              mode: 'lines',
              x: dens.x,
              y: dens.y,
              name: '2 cot θ',
              line: { color: MODEL, width: 2.5 },
            },
          ]}
          layout={{
            ...titled("key's p(θ) = 2 cot θ"),
            xaxis: { type: 'log', title: { text: 'θ (rad)' } },
            yaxis: { type: 'log', title: { text: '2 cot θ' } },
            showlegend: false,
          }}
        />
        <Plot
          ariaLabel="The partial integral minus ln sin epsilon against epsilon: it grows without bound as epsilon shrinks"
          data={[
            {
              type: 'scatter',
              mode: 'lines+markers',
              x: Array.from(series.eps),
              y: Array.from(series.partial),
              name: '−ln sin ε',
              line: { color: SAMPLED },
              marker: { size: 4 },
            },
            {
              type: 'scatter',
              mode: 'markers',
              x: [eps],
              y: [partial],
              name: 'ε chosen',
              marker: { size: 11, color: MODEL },
            },
          ]}
          layout={{
            ...titled('partial integral: no limit'),
            xaxis: { type: 'log', title: { text: 'ε (rad)' }, autorange: 'reversed' },
            yaxis: { title: { text: '−ln sin ε' } },
            legend: LEGEND_INSIDE,
          }}
        />
      </div>
    </div>
  );
}
