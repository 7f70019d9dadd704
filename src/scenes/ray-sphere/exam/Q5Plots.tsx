/**
 * Q5's sweep plots: g(t), the quadratic whose roots are the answer, in view, with its audio trace
 * and table in a fold; Δ along the sweep, with its data and note, in a fold of its own. The sweep's
 * samples (g's window is fixed over the whole sweep) are computed here, in a block that mounts
 * after the page's first render (ui/Deferred), so they are not part of one long first task.
 */
import { useMemo } from 'react';
import { Fold } from '../../../ui/Fold';
import { sweepAt, type Sweep } from '../sweep';
import { sweepSeries } from '../sweepSeries';
import type { RaySphereParams } from '../params';
import { LivePlots, type LiveProps } from '../view/Live';
import { DeltaPlotData, deltaDescription, gDescription, GPlotData, LiveDescribed } from '../view/Described';
import { sweepCoord } from '../view/format';

export function Q5Plots({
  tl,
  modelAt,
  sweep,
  method,
}: LiveProps & { sweep: Sweep; method: RaySphereParams['method'] }) {
  const series = useMemo(() => sweepSeries({ method }, sweep), [method, sweep]);
  const tangentX = useMemo(() => series.tangents.map((tt) => sweepAt(sweep, tt).x), [series, sweep]);
  const live = { tl, modelAt };
  // the sweep's samples, shared by the plots and the Δ plot's table and audio trace
  const data = { sweep, series, tangentX };
  const describeDelta = useMemo(
    () => deltaDescription(series, tangentX, sweep, (tau) => sweepAt(sweep, tau).x),
    [series, tangentX, sweep],
  );
  const xLabel =
    sweep.mode === 'offset'
      ? 'h / r: signed distance of the line from C, in radii'
      : 'ψ / α: angle between d and the direction to C, in angular radii α';
  const note = (
    <p className="rs-small" data-testid="sweep-note">
      Strip under the Δ plot: the {method === 'naive' ? 'textbook' : 'robust'} method’s case at each position
      (grey miss, green two hits, blue inside, red behind, gold tangent).{' '}
      {series.tangents.length
        ? `Δ crosses 0 where the line touches the sphere (tangent, |${sweepCoord(sweep.mode)}| = 1).`
        : 'In this sweep the line never touches the sphere.'}{' '}
      {series.naiveSignWrong > 0 ? (
        <strong data-testid="sweep-naive-wrong" data-value={series.naiveSignWrong}>
          The textbook Δ has the wrong sign (or is 0) at {series.naiveSignWrong} of {series.x.length}{' '}
          positions: rounding, not geometry.
        </strong>
      ) : null}
    </p>
  );
  return (
    <LivePlots
      {...live}
      {...data}
      xLabel={xLabel}
      method={method}
      aroundG={(plot) => (
        <LiveDescribed
          {...live}
          label="g(t) along the ray: the quadratic and its roots"
          describe={gDescription(series.gWindow)}
          quiet
          testId="g-figure"
          after={(m) => (
            <Fold name="g-data" summary="Hear g(t), or read it as a table">
              <GPlotData res={m.chosen} window={series.gWindow} />
            </Fold>
          )}
        >
          {plot}
        </LiveDescribed>
      )}
      aroundDelta={(plot) => (
        <Fold name="delta" summary="Δ along the sweep, robust and textbook">
          <LiveDescribed
            {...live}
            label="Δ against the sweep"
            describe={describeDelta}
            quiet
            testId="delta-figure"
            after={() => <DeltaPlotData {...data} />}
          >
            {plot}
          </LiveDescribed>
          {note}
        </Fold>
      )}
    />
  );
}
