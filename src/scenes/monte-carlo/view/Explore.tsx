/**
 * "Explore further" under Q4: the integrand and the pdf, the convergence and RMSE plots, and the
 * unbiasedness histogram (exam Q2 c). Under ask=1 the worker-run plots are results, hidden (and not
 * run) until revealed.
 */
import { ExploreFurther, Revealed } from '../../../ui';
import type { WorkerFactory } from '../../../workers';
import type { ProblemArgs } from '../jobs';
import type { McTasks } from '../mc.worker';
import type { curves, PdfChoice, SampleTable } from '../model';
import type { PdfKind, Strategy } from '../params';
import { ConvergencePanel } from './ConvergencePanel';
import { HistogramPanel } from './HistogramPanel';
import { IntegrandPanel } from './IntegrandPanel';
import { RmsePanel } from './RmsePanel';

export function McExplore({
  choice,
  curve,
  table,
  a,
  b,
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
  choice: PdfChoice | null;
  curve: ReturnType<typeof curves> | null;
  table: SampleTable | null;
  a: number;
  b: number;
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
  return (
    <ExploreFurther intro="Other integrands and pdfs, stratified and quasi-Monte Carlo points, many runs, run time, and unbiasedness (exam Q2 c).">
      <IntegrandPanel choice={choice} curve={curve} table={table} a={a} b={b} />
      {baseArgs ? (
        <Revealed ask={ask} what="the convergence plots, the RMSE and the histogram of estimates">
          <ConvergencePanel
            args={baseArgs}
            nMax={n}
            exact={exact}
            makeWorker={makeWorker}
            present={present}
          />
          <RmsePanel
            args={baseArgs}
            nMax={Math.min(n, 100_000)}
            runs={runs}
            exact={exact}
            makeWorker={makeWorker}
            onRuns={(r) => setParams({ runs: r })}
          />
          {choice?.ok ? (
            <HistogramPanel
              args={{ ...baseArgs, strategies: selected }}
              N={hn}
              exact={exact}
              makeWorker={makeWorker}
              onN={(v) => setParams({ hn: v })}
            />
          ) : null}
        </Revealed>
      ) : null}
    </ExploreFurther>
  );
}
