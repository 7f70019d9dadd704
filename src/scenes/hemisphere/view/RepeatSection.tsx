/**
 * Q2(c)'s empirical check: repeat the estimate many times with fresh samples (on request) and show
 * the histogram of the estimates around ∫ f dω.
 */
import { Notice } from '../../../ui';
import type { WorkerJob } from '../../../workers';
import type { RepeatResult } from '../jobs';
import type { LobeId } from '../params';
import { RepeatView } from './Q2Panel';

export function RepeatSection({
  repeat,
  fOk,
  exact,
  runs,
  perRun,
  lobe,
  exponent,
  fIsCos,
}: {
  repeat: Pick<WorkerJob<RepeatResult, unknown>, 'result' | 'running' | 'progress' | 'error' | 'run'>;
  /** Whether the integrand compiled. */
  fOk: boolean;
  exact: number | null;
  runs: number;
  perRun: number;
  lobe: LobeId;
  exponent: number;
  fIsCos: boolean;
}) {
  return (
    <>
      <div className="repeat-row">
        <button
          type="button"
          onClick={repeat.run}
          disabled={!fOk || repeat.running}
          data-testid="repeat-button"
        >
          Repeat {runs} times (N = {perRun} each)
        </button>
        {repeat.running ? <span role="status"> running… {Math.round(repeat.progress * 100)} %</span> : null}
        {repeat.error ? <Notice kind="error">{repeat.error.message}</Notice> : null}
      </div>
      {repeat.result && exact !== null ? (
        <RepeatView
          result={repeat.result}
          exact={exact}
          runs={runs}
          perRun={perRun}
          lobe={lobe}
          exponent={exponent}
          fIsCos={fIsCos}
        />
      ) : (
        <p className="small">
          Each run draws {perRun} fresh samples; the histogram of the {runs} estimates should centre on ∫ f
          dω.
        </p>
      )}
    </>
  );
}
