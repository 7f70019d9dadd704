/**
 * "Explore further" under Q4, each panel folded (mounted, and its worker runs started, only when
 * opened; the link's `open=` remembers it): the integrand and the pdf, the convergence plots, the
 * RMSE over runs and against run time, and the unbiasedness histogram (exam Q2 c). Under ask=1 the
 * worker-run plots are results, hidden (and not run) until revealed.
 */
import { ExploreFurther, Revealed } from '../../../ui';
import { Fold } from '../../../ui/Fold';
import type { WorkerFactory } from '../../../workers';
import type { ProblemArgs } from '../jobs';
import type { McTasks } from '../mc.worker';
import type { PdfKind, Strategy } from '../params';
import { ConvergencePanel } from './ConvergencePanel';
import { HistogramPanel } from './HistogramPanel';
import { IntegrandPanel, type IntegrandProps } from './IntegrandPanel';
import { RmsePanel } from './RmsePanel';

export function McExplore({
  integrand,
  baseArgs,
  selected,
  n,
  runs,
  hn,
  exact,
  makeWorker,
  present,
  ask,
  setParams,
}: {
  integrand: IntegrandProps;
  baseArgs: ProblemArgs | null;
  /** The page's own strategy, alone (the histogram's). */
  selected: { pdf: PdfKind; seq: Strategy; label: string }[];
  n: number;
  runs: number;
  hn: number;
  exact: number;
  makeWorker: WorkerFactory<McTasks>;
  present: boolean;
  ask: boolean;
  setParams: (patch: { runs?: number; hn?: number }) => void;
}) {
  // what every worker-run panel below needs: the reference value and the worker to run in
  const run = { exact, makeWorker };
  const hidden = (what: string) => ({ ask, what });
  return (
    <ExploreFurther intro="Other integrands and pdfs, stratified and quasi-Monte Carlo points, many runs, run time, and unbiasedness (exam Q2 c). Each opens on a click.">
      <Fold name="integrand" summary="The integrand and the pdf, with the estimator’s formulas">
        <IntegrandPanel {...integrand} />
      </Fold>
      {baseArgs ? (
        <Fold
          name="convergence"
          summary="Convergence as N grows: the running estimate and |error| per strategy"
        >
          <Revealed {...hidden('the convergence plots')}>
            <ConvergencePanel {...run} args={baseArgs} nMax={n} present={present} />
          </Revealed>
        </Fold>
      ) : null}
      {baseArgs ? (
        <Fold name="rmse" summary="RMSE over independent runs, and accuracy against run time">
          <Revealed {...hidden('the RMSE over runs')}>
            <RmsePanel
              {...run}
              args={baseArgs}
              nMax={Math.min(n, 100_000)}
              runs={runs}
              onRuns={(r) => setParams({ runs: r })}
            />
          </Revealed>
        </Fold>
      ) : null}
      {baseArgs && integrand.choice?.ok ? (
        <Fold name="unbiased" summary="Unbiasedness: a histogram of many independent estimates (Q2 c)">
          <Revealed {...hidden('the histogram of estimates')}>
            <HistogramPanel
              {...run}
              args={{ ...baseArgs, strategies: selected }}
              N={hn}
              onN={(v) => setParams({ hn: v })}
            />
          </Revealed>
        </Fold>
      ) : null}
    </ExploreFurther>
  );
}
