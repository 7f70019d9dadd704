/**
 * Q1(d)'s live answer: do the drawn samples follow p? The sample count, histograms of θ and φ
 * against the marginals and a χ² test on bins of equal solid angle; folded under them, the
 * histograms heard and tabled, and the χ² test's observed and expected counts in 2D.
 */
import { formatNumber, Readout } from '../../../ui';
import { Fold } from '../../../ui/Fold';
import { formatCount } from '../../../ui/format';
import type { SequenceKind } from '../../../core/random';
import type { DrawStats } from '../drawStats';
import type { Lobe } from '../lobe';
import { Histogram2D, MarginalData, MarginalPlots } from './Plots';

export function SampleCheck({
  current,
  lobe,
  inverted,
  kind,
  n,
}: {
  /** The statistics of the current draw (null while they are computed). */
  current: DrawStats | null;
  /** The sampled density (null: none). */
  lobe: Lobe | null;
  inverted: boolean;
  kind: SequenceKind;
  n: number;
}) {
  const sampled = !!lobe;
  const samples = current && sampled ? current.n : null;
  const chi2 = current?.chi2 ?? null;
  return (
    <>
      <div className="readouts">
        <Readout id="samples" label="samples drawn" value={samples} />
        <Readout id="chi2-p" label="χ² p-value" value={chi2 ? chi2.pValue : null} digits={4} />
      </div>
      {lobe ? (
        current ? (
          <>
            <p className="small">
              Do the samples follow p? Histograms of θ and φ against p(θ) and p(φ), and a χ² test on bins of
              equal solid angle.
            </p>
            <MarginalPlots stats={current} lobe={lobe} />
            {chi2 ? (
              <p data-testid="chi2-verdict" className={chi2.pass ? 'verdict ok' : 'verdict bad'}>
                χ² = {formatNumber(chi2.statistic, 5)} with {chi2.dof} degrees of freedom ({chi2.bins} bins of
                equal solid angle over (cos θ, φ)
                {chi2.pooledBins ? `, ${chi2.pooledBins} low-expectation bins pooled` : ''}): p ={' '}
                {formatNumber(chi2.pValue, 4)}.{' '}
                {chi2.pass
                  ? `Accepted at α = ${chi2.alpha}: the samples are consistent with p(ω).`
                  : `Rejected at α = ${chi2.alpha}${chi2.note ? `: ${chi2.note}` : ''}.`}
                {kind !== 'independent'
                  ? ' (The test assumes independent samples; stratified and low-discrepancy sets are more even than chance, so p-values near 1 are expected.)'
                  : ''}
              </p>
            ) : null}
            <Fold
              name="bins"
              summary="The bins: hear the θ and φ histograms or read them as tables, and the χ² test's bins over (cos θ, φ)"
            >
              <MarginalData stats={current} lobe={lobe} />
              <Histogram2D stats={current} />
            </Fold>
          </>
        ) : (
          <p role="status">Drawing {formatCount(n)} samples…</p>
        )
      ) : (
        <p className="small">
          No samples:{' '}
          {inverted ? "the paper's identity gives no density (see (b))." : 'the density is not valid yet.'}
        </p>
      )}
    </>
  );
}
