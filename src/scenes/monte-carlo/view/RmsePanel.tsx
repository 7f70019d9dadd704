/** RMSE over independent (randomized) runs against N, and against the measured run time. */
import { useMemo, useRef } from 'react';
import { Panel, useThrottled, type PlotTrace } from '../../../ui';
import { useAutoRun } from '../../../workers';
import { atRoundingLevel } from '../zeroVariance';
import { sortedByX } from '../compared';
import { formatCount } from '../../../ui/format';
import { REDRAW_MS, useLegendRoom } from './hooks';
import { arr, clampArr, COLORS, CountField, RunBar, strategyLine, type PanelRunProps } from './plotStyle';
import { DescribedPlot, type PlotWords } from './DescribedPlot';
import { describeSeriesSet, seriesTable, type NamedSeries } from './plotWords';

export function RmsePanel({
  args,
  nMax,
  runs,
  exact,
  makeWorker,
  onRuns,
}: PanelRunProps & { nMax: number; runs: number; onRuns: (r: number) => void }) {
  const box = useRef<HTMLDivElement>(null);
  const key = JSON.stringify([args, nMax, runs]);
  const task = useAutoRun(makeWorker, 'rmse', { ...args, nMax, runs }, { key, box, queue: 'monte-carlo' });
  const cur = useThrottled(task.result ?? task.partial, REDRAW_MS, !task.running);
  const rm = useMemo(() => cur?.rmse ?? [], [cur]);
  const rmExactLabels = rm.filter((s) => atRoundingLevel(s.rmse, exact)).map((s) => s.label);

  const rmseData = useMemo<PlotTrace[]>(() => {
    const t: PlotTrace[] = [];
    rm.forEach((s, i) => {
      if (atRoundingLevel(s.rmse, exact)) return;
      const c = COLORS[i % COLORS.length];
      const n = arr(s.n);
      t.push({
        type: 'scatter',
        mode: 'lines',
        x: n,
        y: clampArr(s.hi),
        line: { width: 0, color: c },
        hoverinfo: 'skip',
        showlegend: false,
        legendgroup: s.label,
      });
      t.push({
        type: 'scatter',
        mode: 'lines',
        x: n,
        y: clampArr(s.lo),
        line: { width: 0, color: c },
        fill: 'tonexty',
        fillcolor: c,
        opacity: 0.15,
        hoverinfo: 'skip',
        showlegend: false,
        legendgroup: s.label,
      });
      t.push({
        type: 'scatter',
        mode: 'lines+markers',
        x: n,
        y: clampArr(s.rmse),
        name: `${s.label} (slope ${Number.isFinite(s.slope) ? s.slope.toFixed(2) : '—'})`,
        line: strategyLine(i),
        marker: { size: 5 },
        legendgroup: s.label,
      });
    });
    return t;
  }, [rm, exact]);

  const timeData = useMemo<PlotTrace[]>(
    () =>
      rm.flatMap((s, i) => {
        if (atRoundingLevel(s.rmse, exact)) return [];
        // x = measured time: sorted, so the curve never doubles back (n × cost per sample is
        // already increasing, but a curve against time must not depend on that)
        const pts = sortedByX(
          arr(s.n).flatMap((n, k) =>
            s.timeMs[k] > 0 && Number.isFinite(s.rmse[k]) && s.rmse[k] > 0
              ? [{ x: s.timeMs[k], y: s.rmse[k], n }]
              : [],
          ),
        );
        return {
          type: 'scatter',
          mode: 'lines+markers',
          x: pts.map((p) => p.x),
          y: pts.map((p) => p.y),
          text: pts.map((p) => `N = ${p.n}`),
          name: s.label,
          line: strategyLine(i),
          marker: { size: 5 },
        };
      }),
    [rm, exact],
  );

  // the plots in words and as tables: RMSE (of the shown strategies) against N or against the time
  const words = useMemo(() => {
    const shown = rm.filter((s) => !atRoundingLevel(s.rmse, exact));
    const against = (x: 'n' | 'timeMs', xLabel: string, table: NamedSeries[]): PlotWords => ({
      description: describeSeriesSet(
        shown.map((s) => ({ label: s.label, xs: s[x], ys: s.rmse })),
        { xLabel, yLabel: 'RMSE', logLog: true, empty: 'No runs yet.' },
      ),
      table: seriesTable('N', table),
    });
    return {
      rmse: against(
        'n',
        'N',
        rm.flatMap((s) => [
          { label: `${s.label} RMSE`, xs: s.n, ys: s.rmse },
          { label: `${s.label} 10 %`, xs: s.n, ys: s.lo },
          { label: `${s.label} 90 %`, xs: s.n, ys: s.hi },
        ]),
      ),
      time: against(
        'timeMs',
        'ms',
        shown.flatMap((s) => [
          { label: `${s.label} ms`, xs: s.n, ys: s.timeMs },
          { label: `${s.label} RMSE`, xs: s.n, ys: s.rmse },
        ]),
      ),
    };
  }, [rm, exact]);
  const runsDone = rm[0]?.runs ?? 0;
  const runsNote = `${runsDone} run${runsDone === 1 ? '' : 's'} per strategy so far, N up to ${formatCount(nMax)}`;
  const h = 300 + useLegendRoom();
  return (
    <Panel title="RMSE over independent runs, and against run time" className="mc-plots">
      <div ref={box}>
        <CountField name="runs" value={runs} onChange={onRuns} note={runsNote} />
        <RunBar task={task} label="Independent runs…" />
        <DescribedPlot id="rmse" data={rmseData} height={h} words={words.rmse} />
        <DescribedPlot id="rmse-time" data={timeData} height={h} words={words.time} />
        {rmExactLabels.length ? (
          <p className="mc-note">
            Not drawn: {rmExactLabels.join(', ')} (RMSE at rounding level: zero variance).
          </p>
        ) : null}
        <p className="mc-note">
          Run time of one N-sample estimate = N × the cost per sample measured over all runs in a worker in
          your browser (set-up such as tabulating a pdf is not counted). A curve further down and to the left
          buys more accuracy per millisecond.
        </p>
      </div>
    </Panel>
  );
}
