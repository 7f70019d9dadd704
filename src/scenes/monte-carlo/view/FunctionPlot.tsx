/** f and the pdf (scaled to f's height) on the same axes, with the worked samples marked. */
import { useMemo } from 'react';
import { formatNumber, type PlotTrace } from '../../../ui';
import { arr, COLORS } from './plotStyle';
import { DescribedPlot } from './DescribedPlot';
import { describeSeriesSet, seriesTable } from './plotWords';

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
  // in words, and every 20th grid point (and the last) as a table
  const words = useMemo(() => {
    const f = { label: 'f(x)', xs: curve.x, ys: curve.f };
    const p = { label: 'p(x)', xs: curve.x, ys: curve.p.map((v) => v / curve.scale) };
    const shown = curve.p.some(Number.isFinite) ? [f, p] : [f];
    const keep = (_: number, k: number) => k % 20 === 0 || k === curve.x.length - 1;
    const at = samples.length
      ? ` The worked samples at x = ${samples.map((s) => formatNumber(s[0], 4)).join(', ')}.`
      : '';
    return {
      description:
        describeSeriesSet(shown, { xLabel: 'x', yLabel: 'the value', empty: 'No integrand yet.' }) + at,
      table: seriesTable(
        'x',
        shown.map((s) => ({ ...s, xs: s.xs.filter(keep), ys: s.ys.filter(keep) })),
      ),
    };
  }, [curve, samples]);
  return <DescribedPlot id="integrand" data={data} height={260} words={words} />;
}
