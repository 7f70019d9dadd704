/**
 * Q6(a)'s formula against the exact solid angle as the patch shrinks: the relative difference
 * |dA cos θₗ / r² − Ω| / Ω against the patch side on log–log axes (a line of slope 2: the formula's
 * error is second order in the patch's size), this patch marked, and the same points as a table.
 * Shown in a fold of Q6(a)'s check: its traces and summary are computed only once it is opened.
 */
import { memo, useMemo } from 'react';
import { Plot, ShowAsTable, summarizeSeries, type PlotTrace } from '../../../ui';
import type { PatchModel } from '../patch';
import { fmt } from './format';

export const PatchErrorPlot = memo(function PatchErrorPlot({ patch }: { patch: PatchModel }) {
  const traces: PlotTrace[] = useMemo(
    () => [
      {
        x: Array.from(patch.series.side),
        y: Array.from(patch.series.relError),
        type: 'scatter',
        mode: 'lines',
        name: '|dA cos θ<sub>l</sub> / r² − Ω| / Ω',
        line: { color: 'var(--al-patch)' },
      },
      {
        x: [patch.side],
        y: [Math.abs(patch.relError)],
        type: 'scatter',
        mode: 'markers',
        name: 'this patch',
        marker: { color: 'var(--al-patch)', size: 10 },
      },
    ],
    [patch],
  );
  const { rows, summary } = useMemo(() => {
    const xs = Array.from(patch.series.side);
    const ys = Array.from(patch.series.relError);
    return {
      rows: xs.map((x, i) => [x, ys[i]]),
      summary: summarizeSeries(xs, ys, { xLabel: 'side', yLabel: 'the relative difference', logLog: true }),
    };
  }, [patch]);
  return (
    <>
      <Plot
        label="Relative difference between dA cos θₗ / r² and the exact solid angle of the patch, against the patch side (log–log)"
        description={`${summary} This patch: side ${fmt(patch.side)}, relative difference ${fmt(Math.abs(patch.relError), 3)}.`}
        testId="al-patch-plot"
        data={traces}
        height={240}
        layout={{
          xaxis: { type: 'log', title: { text: 'patch side' } },
          yaxis: { type: 'log', title: { text: 'relative difference' } },
          showlegend: false,
        }}
      />
      <ShowAsTable
        caption="Relative difference |dA cos θₗ / r² − Ω| / Ω against the patch side"
        columns={['patch side', 'relative difference']}
        rows={rows}
        testId="al-patch-table"
      />
    </>
  );
});
