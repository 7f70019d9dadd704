/**
 * Q2: the uniform estimator (2π/N) Σ f and the importance estimator (1/N) Σ f/p with the current
 * lobe, beside ∫ f dω; and "repeat many times": the histogram of many independent estimates
 * centres on the true value (unbiasedness, Q2(c)), computed in a worker.
 */
import { useMemo } from 'react';
import { Notice, Plot, Readout, formatNumber } from '../../../ui';
import { estimateFromTerms, type McEstimate } from '../../../core/estimators';

import type { RepeatResult } from '../jobs';

/** Mean, its standard error and the spread of the finite estimates (Welford, in the core). */
function meanSe(a: Float64Array): { mean: number; se: number; sd: number } {
  const e = estimateFromTerms(a);
  return { mean: e.estimate, se: e.stderr, sd: e.n > 1 ? Math.sqrt(e.variance) : NaN };
}

export function EstimateReadouts({
  exact,
  uniform,
  importance,
  importanceOff,
  exactProblem = null,
  exactNote,
  fNonFinite = 0,
  pZero,
}: {
  exact: number | null;
  uniform: McEstimate | null;
  importance: McEstimate | null;
  importanceOff: string | null;
  /** Why ∫ f dω has no value (divergent, f not finite), shown instead of a number. */
  exactProblem?: string | null;
  exactNote?: string | undefined;
  /** Samples where f itself is NaN or ±∞: then no estimate has a value. */
  fNonFinite?: number;
  /** Importance samples where p = 0 but f ≠ 0 (defaults to the estimate's invalid count). */
  pZero?: number;
}) {
  const fBad = fNonFinite > 0;
  const pBad = pZero ?? (fBad ? 0 : (importance?.invalid ?? 0));
  return (
    <div className="readouts">
      <Readout id="mc-exact" label="∫ f dω (quadrature)" value={exactProblem ? null : exact} digits={8} note={exactProblem ? 'no value' : exactNote} />
      <Readout
        id="mc-uniform"
        label="uniform (2π/N) Σ f"
        value={fBad ? null : (uniform?.estimate ?? null)}
        digits={8}
        note={fBad ? 'no value: f is not finite at some samples' : uniform && Number.isFinite(uniform.stderr) ? `± ${formatNumber(uniform.stderr, 3)} (std. error)` : undefined}
      />
      <Readout
        id="mc-importance"
        label="importance (1/N) Σ f/p"
        value={importanceOff || fBad ? null : (importance?.estimate ?? null)}
        digits={8}
        note={importanceOff ?? (fBad ? 'no value: f is not finite at some samples' : importance && Number.isFinite(importance.stderr) ? `± ${formatNumber(importance.stderr, 3)} (std. error)` : undefined)}
      />
      {exactProblem ? (
        <Notice kind="warn" testId="exact-problem">
          ∫ f dω has no value here: {exactProblem}. The estimators below then have nothing to converge to.
        </Notice>
      ) : null}
      {fBad ? (
        <Notice kind="warn" testId="f-nonfinite">
          f is not finite (NaN or ±∞) at {fNonFinite} of the sampled directions: f is undefined or overflows on part of the hemisphere, so the
          estimates have no value (averaging only the finite terms would be biased). Change f so it is finite everywhere on the hemisphere.
        </Notice>
      ) : null}
      {pBad > 0 ? (
        <Notice kind="warn">
          {pBad} sample(s) landed where p = 0 but f ≠ 0: importance sampling needs p &gt; 0 wherever f ≠ 0, so that estimate is biased.
        </Notice>
      ) : null}
    </div>
  );
}

export function RepeatView({ result, exact, runs, perRun }: { result: RepeatResult; exact: number; runs: number; perRun: number }) {
  const u = useMemo(() => meanSe(result.uniform), [result]);
  const im = useMemo(() => meanSe(result.importance), [result]);
  const hasImp = Number.isFinite(im.mean);
  const data = useMemo(() => {
    // one set of bins for both estimators, so their spreads compare at a glance
    let lo = Infinity;
    let hi = -Infinity;
    for (const arr of hasImp ? [result.uniform, result.importance] : [result.uniform])
      for (const x of arr)
        if (Number.isFinite(x)) {
          lo = Math.min(lo, x);
          hi = Math.max(hi, x);
        }
    const size = hi > lo ? (hi - lo) / 60 : 1;
    const xbins = { start: lo - size / 2, end: hi + size / 2, size };
    const traces: Record<string, unknown>[] = [
      { type: 'histogram', x: Array.from(result.uniform), name: 'uniform', opacity: 0.6, marker: { color: '#1f5fa8' }, xbins, autobinx: false },
    ];
    if (hasImp) traces.push({ type: 'histogram', x: Array.from(result.importance), name: 'importance', opacity: 0.55, marker: { color: '#d0502a' }, xbins, autobinx: false });
    return traces;
  }, [result, hasImp]);
  return (
    <div>
      <Plot
        ariaLabel="Histogram of many independent estimates; both centre on the exact integral"
        data={data}
        layout={{
          barmode: 'overlay',
          title: { text: `${runs} estimates, N = ${perRun} each` },
          xaxis: { title: { text: 'estimate' } },
          yaxis: { title: { text: 'runs' } },
          shapes: Number.isFinite(exact) ? [{ type: 'line', x0: exact, x1: exact, yref: 'paper', y0: 0, y1: 1, line: { color: '#222', width: 2, dash: 'dash' } }] : [],
        }}
      />
      <p className="small" data-testid="repeat-summary">
        Mean of the uniform estimates {formatNumber(u.mean, 6)} ± {formatNumber(u.se, 2)}
        {hasImp ? `, of the importance estimates ${formatNumber(im.mean, 6)} ± ${formatNumber(im.se, 2)}` : ''}; the exact value is{' '}
        {formatNumber(exact, 6)} (dashed line). Spread of one estimate: {formatNumber(u.sd, 3)} uniform
        {hasImp ? `, ${formatNumber(im.sd, 3)} importance` : ''}. Both are unbiased: E[⟨I⟩] = ∫ f dω.
        {hasImp && im.sd > 1.05 * u.sd
          ? ' Here importance sampling is worse than uniform: p is not shaped like f, so f/p is large where p is small (for the exam lobe and f = cos θ, f/p = e^(−φ)/k, huge near φ = 0).'
          : hasImp && im.sd < 0.95 * u.sd
            ? ' Here importance sampling wins: p follows f more closely than the uniform density does.'
            : ''}
      </p>
    </div>
  );
}
