/**
 * Scene `#/hemisphere` (exam Q1, Q2): sample the exam's lobe k cos θ e^φ (or uniform, cosine, Phong,
 * or a typed density) by inversion, watch the samples land, test them by χ², derive the steps with
 * live numbers, and use them for the Q2 Monte Carlo estimators.
 */
import { lazy, Suspense, useMemo, useState } from 'react';
import type { SceneProps } from '../../app/scene';
import { useCompiled, ExprField, NumberField, Notice, Panel, Readout, SceneLayout, Select, Slider, formatNumber } from '../../ui';
import { useWorkerJob } from '../../workers';
import type { SequenceKind } from '../../core/random';
import { lobeFromParams, type DrawStats } from './model';
import { LOBES, MAX_N, POINT_SETS, type HemisphereSchema, type LobeId } from './params';
import { compileThetaPhi } from './expr';
import { UnitSquare } from './view/UnitSquare';
import { Derivation } from './view/Derivation';
import { MarginalPlots, Histogram2D } from './view/Plots';
import { EstimateReadouts, RepeatView } from './view/Q2Panel';
import { InvertedJacobian } from './view/InvertedJacobian';
import type { RepeatArgs, RepeatResult, StatsArgs } from './jobs';
// Static, not lazy: the 3D panel is on the first screen, and a Suspense fallback of another height
// shifted the layout when it arrived (three.js itself still loads lazily, inside Viewport).
import { HemisphereView } from './view/HemisphereView';
import './hemisphere.css';

const StabilityPanel = lazy(() => import('./view/StabilityPanel').then((m) => ({ default: m.StabilityPanel })));

const makeWorker = () => new Worker(new URL('./hemisphere.worker.ts', import.meta.url), { type: 'module' });

const LOBE_OPTIONS: { value: LobeId; label: string }[] = [
  { value: 'exam', label: 'exam: k cos θ e^φ' },
  { value: 'uniform', label: 'uniform' },
  { value: 'cosine', label: 'cosine-weighted' },
  { value: 'phong', label: 'Phong cosⁿθ' },
  { value: 'custom', label: 'typed density p(θ, φ)' },
];
const POINT_OPTIONS = POINT_SETS.map((p) => ({ value: p, label: p === 'halton' ? 'Halton' : p === 'sobol' ? 'Sobol (Owen-scrambled)' : p }));
const REPEAT_RUNS = 1000;

export default function HemisphereScene({ params, setParams, mode }: SceneProps<HemisphereSchema>) {
  const lobeId = (LOBES as readonly string[]).includes(params.lobe) ? (params.lobe as LobeId) : 'exam';
  const kind = params.points as SequenceKind;
  const inverted = params.jacobian === 'inverted';
  const isCustom = lobeId === 'custom';

  const fc = useCompiled(params.f, compileThetaPhi);
  const pc = useCompiled(params.pdf, compileThetaPhi, { enabled: isCustom });
  const customDensity = isCustom && pc.status === 'ok' ? pc.fn : null;
  const { lobe: baseLobe, tab } = useMemo(() => lobeFromParams(lobeId, params.exponent, customDensity), [lobeId, params.exponent, customDensity]);
  const customLobe = tab && tab.ok ? tab.lobe : null;
  const lobe = inverted ? null : baseLobe;

  // ---- statistics of one draw, in a worker (./jobs statsJob) -----------------------------------
  const ready = fc.status !== 'pending' && (!isCustom || pc.status !== 'pending');
  const args: StatsArgs = useMemo(
    () => ({ lobe: lobeId, exponent: params.exponent, pdf: params.pdf, f: params.f, points: kind, seed: params.seed, n: params.n, sampleLobe: !inverted && !!baseLobe }),
    [lobeId, params.exponent, params.pdf, params.f, kind, params.seed, params.n, inverted, baseLobe],
  );
  const stats = useWorkerJob<DrawStats>(makeWorker, 'stats', args, { enabled: ready, delayMs: 60 });
  const current = stats.result ?? null;

  // ---- repeat many times (on request; a change of parameters cancels and clears it) -----------
  const perRun = Math.min(params.n, 256);
  const repeatArgs: RepeatArgs = useMemo(() => ({ ...args, runs: REPEAT_RUNS, perRun }), [args, perRun]);
  const repeat = useWorkerJob<RepeatResult>(makeWorker, 'repeat', repeatArgs, { manual: true });
  const runRepeat = repeat.run;

  // ---- readouts -------------------------------------------------------------------------------
  const k = baseLobe ? baseLobe.k : null;
  const samples = current && lobe ? current.n : null;
  const chi2 = current?.chi2 ?? null;
  const exact = current && Number.isFinite(current.exact) ? current.exact : null;
  const uniformEst = current && fc.status === 'ok' ? current.q2.uniform : null;
  const importanceEst = current && fc.status === 'ok' && lobe ? current.q2.importance : null;
  const importanceOff = inverted ? 'off: the inverted variant cannot be sampled' : !lobe ? 'off: no valid density to sample' : null;

  const controls = (
    <div className="hemi-controls">
      <Select label="Sampling density p(ω)" value={lobeId} options={LOBE_OPTIONS} onChange={(v) => setParams({ lobe: v })} testId="lobe" />
      {lobeId === 'phong' ? <Slider label="Phong exponent n" value={params.exponent} min={0} max={10000} step={1} onChange={(v) => setParams({ exponent: v })} /> : null}
      {isCustom ? (
        <ExprField
          label="p(θ, φ) per steradian (need not be normalized)"
          value={params.pdf}
          onCommit={(s) => setParams({ pdf: s })}
          error={pc.status === 'error' ? pc.message : tab && !tab.ok ? tab.message : null}
          hint="mathjs syntax in theta, phi, e.g. cos(theta)^2 * (2 + cos(phi))"
          testId="pdf-input"
        />
      ) : null}
      <Select
        label="Jacobian p(θ, φ) = …"
        value={params.jacobian as 'correct' | 'inverted'}
        options={[
          { value: 'correct', label: 'sin θ · p(ω) (correct)' },
          { value: 'inverted', label: "p(ω) / sin θ (the key's variant)" },
        ]}
        onChange={(v) => setParams({ jacobian: v })}
        testId="jacobian"
      />
      <Select label="Point set (ξ₁, ξ₂)" value={kind} options={POINT_OPTIONS} onChange={(v) => setParams({ points: v })} testId="points" />
      <Slider label="Samples N" value={params.n} min={1} max={MAX_N} log step={1} onChange={(v) => setParams({ n: Math.round(v) })} testId="n" />
      <NumberField label="Seed" value={params.seed} min={0} max={4294967295} step={1} onChange={(v) => setParams({ seed: Math.round(v) })} />
      <div className="readouts">
        <Readout id="k" label="k (normalization of p(ω))" value={k} digits={8} />
        <Readout id="samples" label="samples drawn" value={samples} />
        <Readout id="chi2-p" label="χ² p-value" value={chi2 ? chi2.pValue : null} digits={4} />
      </div>
      <p className="small stats-status" data-testid="stats-status" data-state={current ? 'ready' : stats.running ? 'running' : 'idle'}>
        {stats.running ? `computing in a worker… ${Math.round(stats.progress * 100)} %` : current ? 'statistics up to date' : ''}
      </p>
    </div>
  );

  const main = (
    <>
      {inverted ? (
        <Panel title="The key's upside-down Jacobian">
          <InvertedJacobian />
        </Panel>
      ) : null}
      {isCustom && pc.status === 'error' ? (
        <Notice kind="error" testId="custom-error">
          The typed density could not be used: {pc.message}. Nothing is sampled until it is fixed.
        </Notice>
      ) : null}
      {isCustom && tab && !tab.ok ? (
        <Notice kind="error" testId="custom-error">
          This is not a valid density: {tab.message}. Nothing is sampled until it is fixed.
        </Notice>
      ) : null}
      {isCustom && tab && tab.ok && tab.warning ? <Notice kind="warn">Approximate: {tab.warning}.</Notice> : null}
      <Panel title="Samples on the hemisphere">
        <div className="hemi-views">
          <HemisphereView lobe={lobe} kind={kind} seed={params.seed} n={params.n} height={mode.present ? 460 : 380} />
          <UnitSquare kind={kind} seed={params.seed} n={params.n} size={mode.present ? 280 : 220} />
        </div>
        {!lobe ? <p className="small">No samples: {inverted ? 'the inverted variant is not a density.' : 'the density is not valid yet.'}</p> : null}
      </Panel>
      {lobe ? (
        <Panel title="Do the samples follow p? (histograms and χ²)">
          {current ? (
            <>
              <MarginalPlots stats={current} />
              <Histogram2D stats={current} />
              {chi2 ? (
                <p data-testid="chi2-verdict" className={chi2.pass ? 'verdict ok' : 'verdict bad'}>
                  χ² = {formatNumber(chi2.statistic, 5)} with {chi2.dof} degrees of freedom ({chi2.bins} bins of equal solid angle over (cos θ, φ)
                  {chi2.pooledBins ? `, ${chi2.pooledBins} low-expectation bins pooled` : ''}): p = {formatNumber(chi2.pValue, 4)}.{' '}
                  {chi2.pass ? `Accepted at α = ${chi2.alpha}: the samples are consistent with p(ω).` : `Rejected at α = ${chi2.alpha}${chi2.note ? `: ${chi2.note}` : ''}.`}
                  {kind !== 'independent'
                    ? ' (The test assumes independent samples; stratified and low-discrepancy sets are more even than chance, so p-values near 1 are expected.)'
                    : ''}
                </p>
              ) : null}
            </>
          ) : (
            <p role="status">Drawing {params.n.toLocaleString('en-US')} samples…</p>
          )}
        </Panel>
      ) : null}
      <Panel title="Derivation (Q1), with live numbers">
        <Derivation lobe={lobeId} exponent={params.exponent} custom={customLobe} customTex={pc.status === 'ok' ? (pc.tex ?? null) : null} inverted={inverted} />
      </Panel>
      <Panel title="Q2: Monte Carlo estimators on the hemisphere">
        <ExprField
          label="Integrand f(θ, φ)"
          value={params.f}
          onCommit={(s) => setParams({ f: s })}
          error={fc.status === 'error' ? fc.message : null}
          hint="mathjs syntax in theta, phi; the default is cos(theta)"
          testId="f-input"
        />
        <EstimateReadouts
          exact={exact}
          uniform={uniformEst}
          importance={importanceEst}
          importanceOff={importanceOff}
          exactProblem={current && fc.status === 'ok' ? current.exactProblem : null}
          exactNote={current?.exactNote}
          fNonFinite={current && fc.status === 'ok' ? current.q2.fNonFinite : 0}
          pZero={current && fc.status === 'ok' ? current.q2.pZero : 0}
        />
        <p className="small">
          Both estimators use the same N points (ξ₁, ξ₂): the uniform one warps them to the hemisphere uniformly (p = 1/2π), the importance one
          with the chosen p{baseLobe ? ` (${baseLobe.label})` : ''}. With f = cos θ and the cosine lobe every term f/p equals π: zero variance.
        </p>
        <div className="repeat-row">
          <button type="button" onClick={runRepeat} disabled={fc.status !== 'ok' || repeat.running} data-testid="repeat-button">
            Repeat {REPEAT_RUNS} times (N = {perRun} each)
          </button>
          {repeat.running ? <span role="status"> running… {Math.round(repeat.progress * 100)} %</span> : null}
          {repeat.error ? <Notice kind="error">{repeat.error}</Notice> : null}
        </div>
        {repeat.result && exact !== null ? <RepeatView result={repeat.result} exact={exact} runs={REPEAT_RUNS} perRun={perRun} /> : null}
      </Panel>
      <Panel title="Numerical stability of the inversion formulas">
        <StabilityDetails />
      </Panel>
    </>
  );

  return <SceneLayout controls={controls} main={main} />;
}

function StabilityDetails() {
  const [open, setOpen] = useState(false);
  return (
    <details onToggle={(e) => setOpen((e.target as HTMLDetailsElement).open)} data-testid="stability-details">
      <summary>Compare ½ arccos(1 − 2ξ) with arcsin √ξ, and ln with log1p, at tiny and near-1 ξ</summary>
      {open ? (
        <Suspense fallback={<p>Loading…</p>}>
          <StabilityPanel />
        </Suspense>
      ) : null}
    </details>
  );
}
