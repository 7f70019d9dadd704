/**
 * Unbiasedness you can test, for one estimate: Student's one-sample t-test (core/verify/ttest; Nori's
 * `ttest`) of an estimate, given as its mean and standard error s/√N over N independent samples,
 * against the exact value it should converge to. A correct estimator passes at level α all but
 * α of the time; a biased one fails once N is large enough for its bias to stand out of the noise.
 * Readouts: `ttest-p` (the two-sided p) and `ttest` (`pass`, `fail`, or `none` where the test
 * cannot run: fewer than two samples, no exact value).
 */
import { studentTTest } from '../core/verify/ttest';
import { formatNumber } from '../core/format';
import { Readout } from './Readout';

/** The level of the test: the chance that a correct estimator fails it. */
export const ESTIMATE_TTEST_ALPHA = 0.01;

export function TTestLine({
  estimate,
  stderr,
  n,
  exact,
  against,
}: {
  estimate: number;
  /** s/√N */
  stderr: number;
  n: number;
  exact: number;
  /** What the exact value is, e.g. "the exact integral 56/3". */
  against: string;
}) {
  const r = studentTTest({ mean: estimate, variance: stderr * stderr * n, n }, exact, ESTIMATE_TTEST_ALPHA);
  const ran = Number.isFinite(r.pValue);
  return (
    <div className="ttest-line">
      <Readout
        id="ttest-p"
        label={`t-test against ${against}: p`}
        value={ran ? r.pValue : null}
        digits={3}
        note={
          ran && Number.isFinite(r.dof)
            ? `t = ${formatNumber(r.t, 3)}, ${r.dof} degrees of freedom`
            : undefined
        }
      />
      <p data-testid="ttest" data-value={ran ? (r.pass ? 'pass' : 'fail') : 'none'}>
        {!ran
          ? 'No t-test: it needs at least two samples and an exact value.'
          : r.pass
            ? `Passes at α = ${ESTIMATE_TTEST_ALPHA}: the estimate is consistent with ${against} (an unbiased estimator fails only ${ESTIMATE_TTEST_ALPHA * 100} % of the time).`
            : `Fails at α = ${ESTIMATE_TTEST_ALPHA}: p < ${ESTIMATE_TTEST_ALPHA}, so the estimate is off ${against} by more than its noise explains (a biased estimator, or the 1 % of runs in which a correct one fails).`}
      </p>
    </div>
  );
}
