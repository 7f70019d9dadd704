/**
 * The page's own estimate under Q4(b): the estimate, s/√N and |error| for the page's settings, the
 * RMSE over randomized runs where s/√N is no error estimate (stratified and quasi-Monte Carlo points),
 * and the run in the worker for large N with its progress, time and failure.
 */
import type { McEstimate } from '../../../core/estimators';
import { formatNumber, Notice, Readout } from '../../../ui';
import { formatCount } from '../../../ui/format';
import { TTestLine } from '../../../ui/TTestLine';
import type { WorkerJob } from '../../../workers';
import type { PdfKind, Strategy } from '../params';
import { estimateHasZeroVariance } from '../zeroVariance';

type Job = Pick<WorkerJob<unknown, unknown>, 'running' | 'progress' | 'error'>;

const SEQ_NAMES: Record<Strategy, string> = {
  independent: 'Independent',
  stratified: 'Stratified (jittered)',
  halton: 'Halton',
  sobol: 'Sobol',
};

export interface RmseInfo {
  seq: Strategy;
  runs: number;
  /** N of the RMSE runs (capped below the page's N). */
  n: number;
  /** The RMSE at that N, null until the runs are done. */
  value: number | null;
  task: Job;
}

export interface BigRun {
  task: Job & { cancel: () => void };
  /** Milliseconds the finished run took, null until it finished. */
  ms: number | null;
}

export function EstimateBlock({
  given,
  n,
  est,
  exact,
  rmse,
  notFromP,
  pdfKind,
  big,
}: {
  /** How many samples were given (null: N drawn samples). */
  given: number | null;
  n: number;
  est: McEstimate | null;
  exact: number | null;
  /** Set for points that are not independent. */
  rmse: RmseInfo | null;
  /** The pdf's name when given samples are used with a pdf they were not drawn from. */
  notFromP: string | null;
  pdfKind: PdfKind;
  /** Set when N is run in the worker. */
  big: BigRun | null;
}) {
  const value = est && est.invalid === 0 ? est.estimate : null;
  const stderr = est && est.invalid === 0 && Number.isFinite(est.stderr) ? est.stderr : null;
  return (
    <>
      <div className="readouts">
        <Readout
          id="estimate"
          label={
            given !== null ? `estimate from the ${given} given samples` : `estimate, N = ${formatCount(n)}`
          }
          value={value}
          digits={10}
        />
        <Readout
          id="stderr"
          label={rmse ? 's/√N (not an error estimate for these points)' : 'standard error s/√N'}
          value={stderr}
          digits={4}
          note={
            est && stderr !== null && estimateHasZeroVariance(est)
              ? 'zero variance: every term f/p is the same number, up to rounding'
              : undefined
          }
        />
        <Readout
          id="abs-error"
          label="|estimate − exact|"
          value={value !== null && exact !== null && Number.isFinite(exact) ? Math.abs(value - exact) : null}
          digits={3}
        />
        {rmse ? (
          <Readout
            id="rmse-at-n"
            label={`RMSE over ${rmse.runs} randomized runs, N = ${formatCount(rmse.n)}`}
            value={rmse.value}
            digits={4}
            note={
              rmse.task.running
                ? `running… ${Math.round(rmse.task.progress * 100)} %`
                : rmse.task.error
                  ? `failed: ${rmse.task.error.message}`
                  : undefined
            }
          />
        ) : null}
      </div>
      {/* drawn independently from p: the estimate can be t-tested against the exact integral */}
      {est &&
      value !== null &&
      stderr !== null &&
      exact !== null &&
      Number.isFinite(exact) &&
      !rmse &&
      notFromP === null &&
      given === null ? (
        <TTestLine estimate={value} stderr={stderr} n={est.n} exact={exact} against="the exact integral" />
      ) : null}
      {rmse ? (
        <Notice kind="warn" testId="stderr-not-error">
          {SEQ_NAMES[rmse.seq]} points are not independent, so the standard error s/√N is not an error
          estimate for them (it treats the points as i.i.d. and usually overstates the error by far). The
          error of this method is measured instead as the RMSE over {rmse.runs} independently randomized runs
          {rmse.n < n ? ` (at N = ${formatCount(rmse.n)})` : ''}.
        </Notice>
      ) : null}
      {notFromP !== null ? (
        <Notice kind="warn" testId="given-not-from-p">
          These samples were typed in, not drawn from {notFromP}. The estimator (1/N) Σ f(xᵢ)/p(xᵢ) is
          unbiased only for xᵢ drawn from p; with given samples the numbers above are only arithmetic on them
          {pdfKind === 'proportional' ? ' (for p ∝ f every term still equals ∫ f dx, whatever the xᵢ)' : ''},
          and s/√N is not an error estimate.
        </Notice>
      ) : null}
      {big && big.task.running ? (
        <p className="mc-progress" role="status">
          Estimating with {formatCount(n)} samples in a worker… {Math.round(big.task.progress * 100)} %{' '}
          <button type="button" onClick={big.task.cancel}>
            Cancel
          </button>
        </p>
      ) : null}
      {big && big.ms !== null ? (
        <p className="mc-note">
          {formatCount(n)} samples took {formatNumber(big.ms, 3)} ms in the worker.
        </p>
      ) : null}
      {big && big.task.error ? <Notice kind="error">The run failed: {big.task.error.message}</Notice> : null}
      {est && est.invalid > 0 ? (
        <Notice kind="error">
          {est.invalid} of the samples have p = 0 where f ≠ 0 (or f is not finite there): no estimate is
          shown, because it would be biased.
        </Notice>
      ) : null}
    </>
  );
}
