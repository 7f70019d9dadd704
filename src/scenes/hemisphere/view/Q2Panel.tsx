/**
 * Q2: the uniform estimator (2π/N) Σ f and the importance estimator (1/N) Σ f/p with the current
 * lobe, beside ∫ f dω; the error each carries (s/√N for independent points only; the RMSE over
 * randomized runs for stratified, Halton and Sobol points); warnings for infinite or huge variance;
 * and "repeat many times": the histogram of many independent estimates centres on the true value
 * (unbiasedness, Q2(c)), computed in a worker.
 */
import { useMemo } from 'react';
import { Notice, Plot, Readout, formatNumber, type PlotTrace } from '../../../ui';
import { titled } from './plotTitle';
import { estimateFromTerms, type McEstimate } from '../../../core/estimators';
import type { SequenceKind } from '../../../core/random';
import type { RmseResult } from '../q2Estimates';
import type { VarianceCheck } from '../varianceCheck';
import type { LobeId } from '../params';
import type { RepeatArgs, RepeatResult } from '../jobs';
import { isCosTheta } from '../expr';
import { BAR_OPACITY, IMPORTANCE, REFERENCE, UNIFORM } from './plotColors';

const KIND_NAME: Record<SequenceKind, string> = {
  independent: 'independent',
  stratified: 'stratified',
  halton: 'Halton',
  sobol: 'Sobol',
};

/** Mean, its standard error and the spread of the finite estimates (Welford, in the core). */
function meanSe(a: Float64Array): { mean: number; se: number; sd: number } {
  const e = estimateFromTerms(a);
  return { mean: e.estimate, se: e.stderr, sd: e.n > 1 ? Math.sqrt(e.variance) : NaN };
}

/** The error note of one estimate: s/√N for independent points, the measured RMSE otherwise. */
function errorNote(est: McEstimate | null, kind: SequenceKind, rmse: number | null): string | undefined {
  if (!est || !Number.isFinite(est.estimate)) return undefined;
  if (kind === 'independent')
    return Number.isFinite(est.stderr) ? `± ${formatNumber(est.stderr, 3)} (std. error s/√N)` : undefined;
  return rmse !== null && Number.isFinite(rmse)
    ? `RMSE ${formatNumber(rmse, 3)} over randomized runs (s/√N does not apply to ${KIND_NAME[kind]} points)`
    : `(s/√N does not apply to ${KIND_NAME[kind]} points)`;
}

/** Why s/√N is not shown as the error for stratified and quasi-random points (with the RMSE that is). */
export function StderrNote({ kind, rmse }: { kind: SequenceKind; rmse: RmseResult | null }) {
  if (kind === 'independent') return null;
  return (
    <Notice kind="warn" testId="stderr-note">
      {KIND_NAME[kind].charAt(0).toUpperCase() + KIND_NAME[kind].slice(1)} points are not independent, so the
      sample standard deviation over √N is not an error estimate for them (it ignores how evenly the points
      cover the square, and usually overstates the error). The error shown is measured instead: the
      root-mean-square error against ∫ f dω over {rmse ? rmse.runs : 16} independently randomized sets of the
      same N (fresh jitter or scrambling each run, seeds derived from the seed)
      {rmse
        ? `: ${formatNumber(rmse.uniform, 3)} uniform${Number.isFinite(rmse.importance) ? `, ${formatNumber(rmse.importance, 3)} importance` : ''}`
        : ''}
      .
    </Notice>
  );
}

export function UniformReadouts({
  exact,
  uniform,
  kind,
  rmse,
  exactProblem = null,
  exactNote,
  fNonFinite = 0,
}: {
  exact: number | null;
  uniform: McEstimate | null;
  kind: SequenceKind;
  rmse: RmseResult | null;
  /** Why ∫ f dω has no value (divergent, f not finite), shown instead of a number. */
  exactProblem?: string | null;
  exactNote?: string | undefined;
  /** Samples where f itself is NaN or ±∞: then no estimate has a value. */
  fNonFinite?: number;
}) {
  const fBad = fNonFinite > 0;
  return (
    <div className="readouts">
      <Readout
        id="mc-exact"
        label="∫ f dω (quadrature)"
        value={exactProblem ? null : exact}
        digits={8}
        note={exactProblem ? 'no value' : exactNote}
      />
      <Readout
        id="mc-uniform"
        label="uniform (2π/N) Σ f"
        value={fBad ? null : (uniform?.estimate ?? null)}
        digits={8}
        note={
          fBad
            ? 'no value: f is not finite at some samples'
            : errorNote(uniform, kind, rmse ? rmse.uniform : null)
        }
      />
      {exactProblem ? (
        <Notice kind="warn" testId="exact-problem">
          ∫ f dω has no value here: {exactProblem}. The estimators then have nothing to converge to.
        </Notice>
      ) : null}
      {fBad ? (
        <Notice kind="warn" testId="f-nonfinite">
          f is not finite (NaN or ±∞) at {fNonFinite} of the sampled directions: f is undefined or overflows
          on part of the hemisphere, so the estimates have no value (averaging only the finite terms would be
          biased). Change f so it is finite everywhere on the hemisphere.
        </Notice>
      ) : null}
    </div>
  );
}

export function ImportanceReadouts({
  importance,
  importanceOff,
  kind,
  rmse,
  fNonFinite = 0,
  pZero,
  infiniteVariance = false,
}: {
  importance: McEstimate | null;
  importanceOff: string | null;
  kind: SequenceKind;
  rmse: RmseResult | null;
  fNonFinite?: number;
  /** Importance samples where p = 0 but f ≠ 0 (defaults to the estimate's invalid count). */
  pZero?: number;
  /** ∫ f²/p dω diverges: s/√N is then no error estimate either. */
  infiniteVariance?: boolean;
}) {
  const fBad = fNonFinite > 0;
  const seNote =
    infiniteVariance && importance && Number.isFinite(importance.stderr) && kind === 'independent'
      ? `s/√N = ${formatNumber(importance.stderr, 3)}, meaningless here (infinite variance)`
      : errorNote(importance, kind, rmse ? rmse.importance : null);
  const pBad = pZero ?? (fBad ? 0 : (importance?.invalid ?? 0));
  return (
    <div className="readouts">
      <Readout
        id="mc-importance"
        label="importance (1/N) Σ f/p"
        value={importanceOff || fBad ? null : (importance?.estimate ?? null)}
        digits={8}
        note={importanceOff ?? (fBad ? 'no value: f is not finite at some samples' : seNote)}
      />
      {pBad > 0 ? (
        <Notice kind="warn">
          {pBad} sample(s) landed where p = 0 but f ≠ 0: importance sampling needs p &gt; 0 wherever f ≠ 0, so
          that estimate is biased.
        </Notice>
      ) : null}
    </div>
  );
}

/** What the chosen lobe does to f/p, for the summaries (not always the exam lobe). */
export function lobeExplanation(lobe: LobeId, exponent: number, fIsCos: boolean): string {
  if (!fIsCos) return 'p is not shaped like f here, so f/p is large where p is small compared with f.';
  switch (lobe) {
    case 'exam':
      return 'For the exam lobe and f = cos θ, f/p = e⁻ᵠ/k: p grows like eᵠ while f does not depend on φ, so the terms are huge near φ = 0 where p is small.';
    case 'phong':
      return exponent > 1
        ? `For the Phong lobe with n = ${formatNumber(exponent, 6)} and f = cos θ, f/p = 2π cos¹⁻ⁿ θ/(n + 1): p vanishes faster than f at the horizon, so the terms blow up there${exponent >= 3 ? ' (infinite variance for n ≥ 3)' : ''}.`
        : `For the Phong lobe with n = ${formatNumber(exponent, 6)} and f = cos θ, f/p = 2π cos¹⁻ⁿ θ/(n + 1) stays bounded.`;
    case 'cosine':
      return 'For the cosine lobe and f = cos θ, f/p = π for every sample: p is exactly proportional to f (zero variance).';
    case 'uniform':
      return 'The uniform lobe p = 1/(2π) makes the importance estimator the uniform one.';
    case 'custom':
      return 'For the typed density, f/p is large wherever p is small compared with f = cos θ.';
  }
}

/** Infinite or huge variance of the importance estimator (by quadrature of ∫ f²/p dω). */
export function VarianceWarning({
  v,
  lobe,
  exponent,
  fIsCos,
}: {
  v: VarianceCheck | null;
  lobe: LobeId;
  exponent: number;
  fIsCos: boolean;
}) {
  if (!v) return null;
  if (v.infinite)
    return (
      <Notice kind="warn" testId="variance-warning">
        <strong>Infinite variance.</strong> ∫ f²/p dω diverges, so Var[f(X)/p(X)] is infinite: the importance
        estimate is still unbiased, but its standard error means nothing, it converges slower than 1/√N, and
        rare huge terms make it jump.{' '}
        {lobe === 'phong' && fIsCos
          ? `Here f/p ∝ cos¹⁻ⁿ θ, so f²/p ∝ cos²⁻ⁿ θ and ∫ cos²⁻ⁿ θ sin θ dθ diverges at the horizon for n ≥ 3 (n = ${formatNumber(exponent, 6)}).`
          : lobeExplanation(lobe, exponent, fIsCos)}
      </Notice>
    );
  if (v.ratio > 10)
    return (
      <Notice kind="warn" testId="variance-warning">
        <strong>Huge variance.</strong> One importance term varies {formatNumber(v.ratio, 3)} times as much as
        one uniform term (Var {formatNumber(v.importanceVar, 4)} against {formatNumber(v.uniformVar, 4)}, by
        quadrature): this p makes the estimate worse, not better. {lobeExplanation(lobe, exponent, fIsCos)}
      </Notice>
    );
  return null;
}

export function RepeatView({
  result,
  exact,
  args,
}: {
  result: RepeatResult;
  exact: number;
  /** The arguments of the run: its counts, and the lobe and f that the summary explains. */
  args: Pick<RepeatArgs, 'runs' | 'perRun' | 'lobe' | 'exponent' | 'f'>;
}) {
  const { runs, perRun, lobe, exponent } = args;
  const fIsCos = isCosTheta(args.f);
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
    const traces: PlotTrace[] = [
      {
        type: 'histogram',
        x: Array.from(result.uniform),
        name: 'uniform',
        opacity: BAR_OPACITY,
        marker: { color: UNIFORM },
        xbins,
      },
    ];
    if (hasImp)
      traces.push({
        type: 'histogram',
        x: Array.from(result.importance),
        name: 'importance',
        opacity: BAR_OPACITY,
        marker: { color: IMPORTANCE },
        xbins,
      });
    return traces;
  }, [result, hasImp]);
  return (
    <div>
      <Plot
        ariaLabel="Histogram of many independent estimates; both centre on the exact integral"
        data={data}
        layout={{
          barmode: 'overlay',
          ...titled(`${runs} estimates, N = ${perRun} each`),
          xaxis: { title: { text: 'estimate' } },
          yaxis: { title: { text: 'runs' } },
          shapes: Number.isFinite(exact)
            ? [
                {
                  type: 'line',
                  x0: exact,
                  x1: exact,
                  yref: 'paper',
                  y0: 0,
                  y1: 1,
                  line: { color: REFERENCE, width: 2, dash: 'dash' },
                },
              ]
            : [],
        }}
      />
      <p className="small" data-testid="repeat-summary">
        Mean of the uniform estimates {formatNumber(u.mean, 6)} ± {formatNumber(u.se, 2)}
        {hasImp
          ? `, of the importance estimates ${formatNumber(im.mean, 6)} ± ${formatNumber(im.se, 2)}`
          : ''}
        ; the exact value is {formatNumber(exact, 6)} (dashed line). Spread of one estimate:{' '}
        {formatNumber(u.sd, 3)} uniform
        {hasImp ? `, ${formatNumber(im.sd, 3)} importance` : ''}. Both are unbiased: E[⟨I⟩] = ∫ f dω (the runs
        are independent, so ± here is a valid standard error of the mean).
        {hasImp && im.sd > 1.05 * u.sd
          ? ` Here importance sampling is worse than uniform. ${lobeExplanation(lobe, exponent, fIsCos)}`
          : hasImp && im.sd < 0.95 * u.sd
            ? ` Here importance sampling wins: p follows f more closely than the uniform density does. ${lobeExplanation(lobe, exponent, fIsCos)}`
            : ''}
      </p>
    </div>
  );
}
