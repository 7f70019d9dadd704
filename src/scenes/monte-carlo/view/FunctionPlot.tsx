/** f and the pdf (scaled to f's height) on the same axes, with the worked samples marked. */
import { useMemo } from 'react';
import { formatNumber, Plot, type PlotTrace } from '../../../ui';
import { arr, COLORS, L_FUNC } from './plotStyle';

/** f and p × scale on the same axes, with the worked samples marked. */
export function FunctionPlot({
  curve,
  samples,
  a,
  b,
}: {
  curve: { x: Float64Array; f: Float64Array; p: Float64Array; scale: number };
  samples: [number, number][];
  a: number;
  b: number;
}) {
  const data = useMemo<PlotTrace[]>(() => {
    const t: PlotTrace[] = [
      {
        type: 'scatter',
        mode: 'lines',
        x: arr(curve.x),
        y: arr(curve.f),
        name: 'f(x)',
        line: { color: COLORS[0], width: 2.5 },
      },
    ];
    if (curve.p.some(Number.isFinite)) {
      t.push({
        type: 'scatter',
        mode: 'lines',
        x: arr(curve.x),
        y: arr(curve.p),
        name: `p(x) × ${formatNumber(curve.scale, 3)}`,
        line: { color: COLORS[1], width: 2, dash: 'dash' },
      });
    }
    const inside = samples.filter(([x]) => x >= a && x <= b);
    if (inside.length) {
      t.push({
        type: 'scatter',
        mode: 'markers',
        x: inside.map((s) => s[0]),
        y: inside.map((s) => s[1]),
        name: 'samples xᵢ, f(xᵢ)',
        marker: { color: COLORS[2], size: 9, symbol: 'circle-open', line: { width: 2 } },
      });
    }
    return t;
  }, [curve, samples, a, b]);
  return (
    <Plot
      data={data}
      height={260}
      ariaLabel="The integrand f(x) and the sampling pdf p(x), scaled to the same height, over [a, b]"
      layout={L_FUNC}
    />
  );
}
