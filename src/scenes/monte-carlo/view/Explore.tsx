/**
 * "Explore further" under Q4: the integrand and the pdf, the convergence and RMSE plots, and the
 * unbiasedness histogram (exam Q2 c). Under ask=1 the worker-run plots are results, hidden (and not
 * run) until revealed.
 */
import { ExploreFurther, Revealed } from '../../../ui';
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
  return (
    <ExploreFurther intro="Other integrands and pdfs, stratified and quasi-Monte Carlo points, many runs, run time, and unbiasedness (exam Q2 c).">
      <IntegrandPanel {...integrand} />
      {baseArgs ? (
        <Revealed ask={ask} what="the convergence plots, the RMSE and the histogram of estimates">
          <ConvergencePanel {...run} args={baseArgs} nMax={n} present={present} />
          <RmsePanel
            {...run}
            args={baseArgs}
            nMax={Math.min(n, 100_000)}
            runs={runs}
            onRuns={(r) => setParams({ runs: r })}
          />
          {integrand.choice?.ok ? (
            <HistogramPanel
              {...run}
              args={{ ...baseArgs, strategies: selected }}
              N={hn}
              onN={(v) => setParams({ hn: v })}
            />
          ) : null}
        </Revealed>
      ) : null}
    </ExploreFurther>
  );
}
