/**
 * The running estimate as data for readers who cannot see the plot: an audio trace (pitch follows
 * the estimate, a tick where it crosses the reference) and a table, both read out at the counts
 * of describe.ts's runningPoints up to the samples arrived. Under the stage (not on it), so the
 * stage stays one screen; its sample run is its own (the same stream as the stage's: the same
 * numbers), computed in its own render.
 */
import { memo, useMemo } from 'react';
import { AudioTrace, ShowAsTable, type TraceEvent } from '../../../ui';
import { formatNumber } from '../../../ui/Readout';
import type { LightStrategy } from '../../../core/lights';
import { animationFrame, sampleRun } from '../animation';
import type { AreaLightModel } from '../model';
import { STRATEGY_SHORT } from '../strategies';
import { referenceCrossings, runningRows } from './describe';

const fmt4 = (v: number) => (Number.isFinite(v) ? formatNumber(v, 4).replace(/^-/, '−') : '—');

export const RunningData = memo(function RunningData({
  model,
  strategy,
  count,
  seed,
  t,
  reference,
}: {
  model: AreaLightModel;
  strategy: LightStrategy;
  /** Samples in the animation. */
  count: number;
  seed: number;
  /** The timeline's position (samples arrived). */
  t: number;
  reference: number;
}) {
  const run = useMemo(() => sampleRun(model, strategy, count, seed), [model, strategy, count, seed]);
  const { k } = animationFrame(run, t);
  const { rows, xs, ys, events } = useMemo(() => {
    const rows = runningRows(run, k);
    const xs = rows.map((r) => r[0]);
    const ys = rows.map((r) => r[1]);
    const events: TraceEvent[] = referenceCrossings(run, xs, reference).map((x) => ({
      x,
      kind: 'zero',
      label: 'crosses the reference',
    }));
    return { rows, xs, ys, events };
  }, [run, k, reference]);
  const ref = Number.isFinite(reference) ? `, reference ${fmt4(reference)}` : '';
  return (
    <div className="al-running-data" role="group" aria-label="The running estimate as sound and as a table">
      <AudioTrace
        label="the running estimate against samples k"
        xs={xs}
        ys={ys}
        xLabel="k"
        yLabel="estimate"
        events={events}
        format={fmt4}
        testId="al-running-audio"
      />
      <ShowAsTable
        caption={`Running estimate (${STRATEGY_SHORT[run.strategy]}) after k samples${ref}`}
        columns={['k', 'running estimate', 'standard error']}
        rows={rows}
        format={fmt4}
        testId="al-running-table"
      />
    </div>
  );
});
