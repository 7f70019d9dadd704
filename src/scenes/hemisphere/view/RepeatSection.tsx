/**
 * Q2(c)'s empirical check: repeat the estimate many times with fresh samples (on request) and show
 * the histogram of the estimates around ∫ f dω.
 */
import type { ComponentProps } from 'react';
import { Notice } from '../../../ui';
import type { WorkerJob } from '../../../workers';
import type { RepeatResult } from '../jobs';
import { RepeatView } from './Q2Panel';

export function RepeatSection({
  repeat,
  fOk,
  exact,
  args,
}: {
  repeat: Pick<WorkerJob<RepeatResult, unknown>, 'result' | 'running' | 'progress' | 'error' | 'run'>;
  /** Whether the integrand compiled. */
  fOk: boolean;
  exact: number | null;
  args: ComponentProps<typeof RepeatView>['args'];
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
          Repeat {args.runs} times (N = {args.perRun} each)
        </button>
        {repeat.running ? <span role="status"> running… {Math.round(repeat.progress * 100)} %</span> : null}
        {repeat.error ? <Notice kind="error">{repeat.error.message}</Notice> : null}
      </div>
      {repeat.result && exact !== null ? (
        <RepeatView result={repeat.result} exact={exact} args={args} />
      ) : (
        <p className="small">
          Each run draws {args.perRun} fresh samples; the histogram of the {args.runs} estimates should centre
          on ∫ f dω.
        </p>
      )}
    </>
  );
}
