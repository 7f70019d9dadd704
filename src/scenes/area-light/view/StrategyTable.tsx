/**
 * The three strategies side by side at n samples each, against the reference: a panel of "Explore
 * further". Up to SYNC_MAX samples per strategy the estimates are computed here, on the main
 * thread, one strategy per task (so a phone's render is never one long task); beyond, the scene's
 * worker run supplies them (it also feeds Q6(c)'s answer). Same seeds and streams: the same numbers.
 * The work starts only when the panel mounts, that is when its fold is opened.
 */
import { memo, useEffect, useRef, useState } from 'react';
import type { LightStrategy } from '../../../core/lights';
import { Panel, Readout } from '../../../ui';
import { runChunked } from '../../../ui/chunked';
import { ScrollBox } from '../../../ui/ScrollBox';
import { estimateOne, SYNC_MAX, type AreaLightModel, type StrategyEstimate } from '../model';
import { STRATEGIES, STRATEGY_LABEL, STRATEGY_SHORT } from '../strategies';
import { fmt } from './format';

/**
 * The three estimates, null until computed. `estKey` names what they depend on (the model changes
 * identity with every animation frame; the estimates do not), `fromWorker` is the worker's list
 * when n > SYNC_MAX.
 */
function useStrategyEstimates(
  model: AreaLightModel,
  n: number,
  seed: number,
  estKey: string,
  fromWorker: StrategyEstimate[] | null,
): StrategyEstimate[] | null {
  const big = n > SYNC_MAX;
  const [done, setDone] = useState<{ key: string; list: StrategyEstimate[] } | null>(null);
  const latestModel = useRef(model);
  latestModel.current = model;
  useEffect(() => {
    if (big) return;
    const m = latestModel.current;
    const list: StrategyEstimate[] = [];
    const cancels = STRATEGIES.map((s) =>
      runChunked(() => {
        list.push(estimateOne(m, s, n, seed));
        if (list.length === STRATEGIES.length) setDone({ key: estKey, list });
      }),
    );
    return () => cancels.forEach((c) => c());
  }, [big, estKey, n, seed]);
  if (big) return fromWorker;
  return done?.key === estKey ? done.list : null;
}

export const StrategyTable = memo(function StrategyTable({
  model,
  strategy,
  n,
  seed,
  target,
  estKey,
  fromWorker,
}: {
  model: AreaLightModel;
  strategy: LightStrategy;
  n: number;
  seed: number;
  target: number;
  /** What the estimates depend on, as a string (the scene's parameters but the animation's). */
  estKey: string;
  /** The worker's three estimates when n > SYNC_MAX (null while they are computed). */
  fromWorker: StrategyEstimate[] | null;
}) {
  const estimates = useStrategyEstimates(model, n, seed, estKey, fromWorker);
  return (
    <Panel title="Three strategies for the same integral">
      <p>
        Solid-angle sampling draws ω uniformly over the light’s spherical rectangle (pdf 1/Ω), so each term is
        Ω f L V cos θ; cosine sampling draws ω with pdf cos θ / π, so each term is ρ L V when the ray hits the
        light and 0 when it misses. All three are unbiased; they differ in variance. All samples are
        independent pseudo-random draws, so the standard error s/√N is a valid error estimate for each.
      </p>
      <ScrollBox label="All three strategies, their estimates and standard errors">
        <table className="al-table">
          <caption>
            All three strategies, n = {n} each, seed {seed}
          </caption>
          <thead>
            <tr>
              <th scope="col">strategy</th>
              <th scope="col">estimate</th>
              <th scope="col">std. error σ</th>
              <th scope="col">(est.&nbsp;−&nbsp;ref.)/σ</th>
            </tr>
          </thead>
          <tbody>
            {estimates === null ? (
              <tr>
                <td colSpan={4}>
                  <progress aria-label="Estimating the three strategies" /> Estimating…
                </td>
              </tr>
            ) : null}
            {(estimates ?? []).map((e) => (
              <tr key={e.strategy} className={e.strategy === strategy ? 'al-current' : undefined}>
                <th scope="row" title={STRATEGY_LABEL[e.strategy]}>
                  {STRATEGY_SHORT[e.strategy]}
                </th>
                <td>
                  <Readout id={`estimate-${e.strategy}`} label="" value={e.estimate} digits={5} />
                </td>
                <td>
                  <Readout id={`stderr-${e.strategy}`} label="" value={e.stderr} digits={2} />
                </td>
                <td>
                  {e.stderr > 0 && Number.isFinite(target) ? fmt((e.estimate - target) / e.stderr, 3) : '—'}
                </td>
              </tr>
            ))}
          </tbody>
        </table>
      </ScrollBox>
    </Panel>
  );
});
