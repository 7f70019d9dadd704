/**
 * Scene `#/hemisphere` (exam Q1, Q2), exam first (issue 11): the question as the exam states it,
 * part by part, each with its written derivation (live numbers) and its live answer; then "Explore
 * further" (other lobes' derivations, floating-point stability). The figure that teaches Q1 — the
 * warp morph of the unit square onto the hemisphere, on the shared timeline (issue 12) — sits
 * right after the question. Samples, χ² and the Q2 estimators are computed in a worker.
 */
import { formatCount } from '../../ui/format';
import { lazy, memo, Suspense, useMemo, useRef, useState, type ComponentProps } from 'react';
import type { SceneProps } from '../../kit/scene';
import {
  useCompiled,
  ExprField,
  NumberField,
  Notice,
  Panel,
  Readout,
  Select,
  Slider,
  Toggle,
  TimelineTransport,
  useCoarsePosition,
  useTimeline,
  useTimelineFrame,
  prefersReducedMotion,
  formatNumber,
  type Timeline,
} from '../../ui';
import { ExamQuestion, ExploreFurther } from '../../ui/exam';
import { MathTex } from '../../ui';
import { useWorkerJob, workerFactory } from '../../workers';
import type { HemisphereTasks } from './hemisphere.worker';
import { nextTask } from '../../ui/chunked';
import { fillSequence2D, type SequenceKind } from '../../core/random';
import {
  animDuration,
  animFrame,
  examChecksCached,
  examInversion,
  lobeFromParams,
  type AnimFrame,
  type AnimKind,
  type Lobe,
} from './model';
import { ANIMS, LOBES, MAX_N, POINT_SETS, type HemisphereSchema, type LobeId } from './params';
import { compileThetaPhi, compileThetaPhiFast, isCosTheta } from './expr';
import { UnitSquare } from './view/UnitSquare';
import { Derivation } from './view/Derivation';
import { MarginalPlots, Histogram2D } from './view/Plots';
import { ImportanceReadouts, RepeatView, StderrNote, UniformReadouts, VarianceWarning } from './view/Q2Panel';
import { InvertedJacobian } from './view/InvertedJacobian';
import { ExamQ1 } from './view/ExamQ1';
import { ExamQ2, lobeTexOf } from './view/ExamQ2';
import type { RepeatArgs, StatsArgs } from './jobs';
// Static, not lazy: the 3D panel is on the first screen, and a Suspense fallback of another height
// shifted the layout when it arrived (three.js itself still loads lazily, inside Viewport).
import { HemisphereView } from './view/HemisphereView';
import './hemisphere.css';

const StabilityPanel = lazy(() =>
  import('./view/StabilityPanel').then((m) => ({ default: m.StabilityPanel })),
);

const makeWorker = workerFactory<HemisphereTasks>(
  () => new Worker(new URL('./hemisphere.worker.ts', import.meta.url), { type: 'module' }),
);

const LOBE_OPTIONS: { value: LobeId; label: string }[] = [
  { value: 'exam', label: 'exam: k cos θ e^φ' },
  { value: 'uniform', label: 'uniform' },
  { value: 'cosine', label: 'cosine-weighted' },
  { value: 'phong', label: 'Phong cosⁿθ' },
  { value: 'custom', label: 'typed density p(θ, φ)' },
];
const POINT_OPTIONS = POINT_SETS.map((p) => ({
  value: p,
  label: p === 'halton' ? 'Halton' : p === 'sobol' ? 'Sobol (Owen-scrambled)' : p,
}));
const ANIM_OPTIONS: { value: AnimKind; label: string }[] = [
  { value: 'warp', label: 'warp morph: square → hemisphere' },
  { value: 'grow', label: 'samples appear, 1 → N' },
];
const REPEAT_RUNS = 1000;

const SquareMemo = memo(UnitSquare);

// The exam's quadrature checks (a few ms of adaptive 2D integration) in a task of their own as the
// scene's code arrives, not inside its first render (issue 15); the render reads the cached result.
nextTask(() => void examChecksCached());

export default function HemisphereScene({ params, setParams, mode }: SceneProps<HemisphereSchema>) {
  const lobeId = (LOBES as readonly string[]).includes(params.lobe) ? (params.lobe as LobeId) : 'exam';
  const kind = params.points as SequenceKind;
  const anim: AnimKind = (ANIMS as readonly string[]).includes(params.anim)
    ? (params.anim as AnimKind)
    : 'warp';
  const inverted = params.jacobian === 'inverted';
  const isCustom = lobeId === 'custom';
  const fIsCos = isCosTheta(params.f);

  const fc = useCompiled(params.f, compileThetaPhi, { fast: compileThetaPhiFast });
  const pc = useCompiled(params.pdf, compileThetaPhi, { enabled: isCustom });
  const customDensity = isCustom && pc.status === 'ok' ? pc.fn : null;
  const { lobe: baseLobe, tab } = useMemo(
    () => lobeFromParams(lobeId, params.exponent, customDensity),
    [lobeId, params.exponent, customDensity],
  );
  const customLobe = tab && tab.ok ? tab.lobe : null;
  const lobe = inverted ? null : baseLobe;

  // ---- statistics of one draw, in a worker (./jobs statsJob) -----------------------------------
  const ready = fc.status !== 'pending' && (!isCustom || pc.status !== 'pending');
  const args: StatsArgs = useMemo(
    () => ({
      lobe: lobeId,
      exponent: params.exponent,
      pdf: params.pdf,
      f: params.f,
      points: kind,
      seed: params.seed,
      n: params.n,
      sampleLobe: !inverted && !!baseLobe,
    }),
    [lobeId, params.exponent, params.pdf, params.f, kind, params.seed, params.n, inverted, baseLobe],
  );
  // its readouts and plots are below the first screen: the opening run waits for the page to load
  const stats = useWorkerJob(makeWorker, 'stats', args, {
    enabled: ready,
    delayMs: 60,
    afterSettle: true,
  });
  const current = stats.result ?? null;

  // ---- repeat many times (on request; a change of parameters cancels and clears it) -----------
  const perRun = Math.min(params.n, 256);
  const repeatArgs: RepeatArgs = useMemo(() => ({ ...args, runs: REPEAT_RUNS, perRun }), [args, perRun]);
  const repeat = useWorkerJob(makeWorker, 'repeat', repeatArgs, { manual: true });
  const runRepeat = repeat.run;

  // ---- readouts -------------------------------------------------------------------------------
  const k = baseLobe ? baseLobe.k : null;
  const samples = current && lobe ? current.n : null;
  const chi2 = current?.chi2 ?? null;
  const exact = current && Number.isFinite(current.exact) ? current.exact : null;
  const uniformEst = current && fc.status === 'ok' ? current.q2.uniform : null;
  const importanceEst = current && fc.status === 'ok' && lobe ? current.q2.importance : null;
  const importanceOff = inverted
    ? "off: the paper's identity gives no density to sample"
    : !lobe
      ? 'off: no valid density to sample'
      : null;
  const rmse = current && fc.status === 'ok' ? current.rmse : null;

  const checks = useMemo(() => examChecksCached(), []);
  const firstXi = useMemo(() => {
    if (params.n < 1) return null;
    const u = new Float64Array(2);
    fillSequence2D(kind, params.seed, params.n, u, 0, 1, 0);
    return { xi1: u[0], xi2: u[1] };
  }, [kind, params.seed, params.n]);

  const densityProblem =
    isCustom && pc.status === 'error' ? (
      <Notice kind="error" testId="custom-error">
        The typed density could not be used: {pc.message}. Nothing is sampled until it is fixed.
      </Notice>
    ) : isCustom && tab && !tab.ok ? (
      <Notice kind="error" testId="custom-error">
        This is not a valid density: {tab.message}. Nothing is sampled until it is fixed.
      </Notice>
    ) : null;

  const settings = (
    <div className="hemi-controls">
      <Select
        label="Sampling density p(ω)"
        value={lobeId}
        options={LOBE_OPTIONS}
        onChange={(v) => setParams({ lobe: v })}
        testId="lobe"
      />
      {lobeId === 'phong' ? (
        <Slider
          label="Phong exponent n"
          value={params.exponent}
          min={0}
          max={10000}
          step={1}
          onChange={(v) => setParams({ exponent: v })}
        />
      ) : null}
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
          { value: 'inverted', label: 'p(ω) / sin θ (as on the paper)' },
        ]}
        onChange={(v) => setParams({ jacobian: v })}
        testId="jacobian"
      />
      <Select
        label="Point set (ξ₁, ξ₂)"
        value={kind}
        options={POINT_OPTIONS}
        onChange={(v) => setParams({ points: v })}
        testId="points"
      />
      <Slider
        label="Samples N"
        value={params.n}
        min={1}
        max={MAX_N}
        log
        step={1}
        onChange={(v) => setParams({ n: Math.round(v) })}
        testId="n"
      />
      <NumberField
        label="Seed"
        value={params.seed}
        min={0}
        max={4294967295}
        step={1}
        onChange={(v) => setParams({ seed: Math.round(v) })}
      />
      <p
        className="small stats-status"
        data-testid="stats-status"
        data-state={current ? 'ready' : stats.running ? 'running' : stats.waiting ? 'waiting' : 'idle'}
      >
        {stats.running
          ? `computing in a worker… ${Math.round(stats.progress * 100)} %`
          : current
            ? 'statistics up to date'
            : stats.waiting
              ? 'statistics start once the page has loaded…'
              : ''}
      </p>
    </div>
  );

  const answer1a = (
    <div className="readouts">
      <Readout
        id="k"
        label="k (normalization of p(ω))"
        value={k}
        digits={8}
        note={
          lobeId === 'exam' ? '= 2/expm1(2π)' : `of the chosen lobe (${baseLobe ? baseLobe.label : 'none'})`
        }
      />
    </div>
  );

  const answer1d = (
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
            <MarginalPlots stats={current} />
            <Histogram2D stats={current} />
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
          </>
        ) : (
          <p role="status">Drawing {formatCount(params.n)} samples…</p>
        )
      ) : (
        <p className="small">
          No samples:{' '}
          {inverted ? "the paper's identity gives no density (see (b))." : 'the density is not valid yet.'}
        </p>
      )}
    </>
  );

  const otherLobe =
    lobeId !== 'exam' ? (
      <Notice kind="info" testId="other-lobe">
        The figure, the checks in (d) and the estimates of Q2 use the chosen density,{' '}
        {baseLobe ? baseLobe.label : 'the typed density'}; the derivation above is the exam&apos;s, for k cos
        θ e^φ. The chosen density&apos;s own derivation is under Explore further.
      </Notice>
    ) : null;

  const lobeTex = lobeTexOf(lobeId, params.exponent, k, pc.status === 'ok' ? (pc.tex ?? null) : null);
  const repeatSection = (
    <>
      <div className="repeat-row">
        <button
          type="button"
          onClick={runRepeat}
          disabled={fc.status !== 'ok' || repeat.running}
          data-testid="repeat-button"
        >
          Repeat {REPEAT_RUNS} times (N = {perRun} each)
        </button>
        {repeat.running ? <span role="status"> running… {Math.round(repeat.progress * 100)} %</span> : null}
        {repeat.error ? <Notice kind="error">{repeat.error.message}</Notice> : null}
      </div>
      {repeat.result && exact !== null ? (
        <RepeatView
          result={repeat.result}
          exact={exact}
          runs={REPEAT_RUNS}
          perRun={perRun}
          lobe={lobeId}
          exponent={params.exponent}
          fIsCos={fIsCos}
        />
      ) : (
        <p className="small">
          Each run draws {perRun} fresh samples; the histogram of the {REPEAT_RUNS} estimates should centre on
          ∫ f dω.
        </p>
      )}
    </>
  );

  return (
    <div className="hemi-page">
      <ExamQuestion
        n={1}
        title="Sampling a hemisphere PDF by inversion"
        intro={
          <p>
            <MathTex tex={`p(\\omega) = k\\cos\\theta\\,e^{\\phi}`} /> on the upper hemisphere (θ ∈ [0, π/2]
            from the normal +z, φ ∈ [0, 2π) from +x): (a) normalize it; (b) change variables, find the
            marginals; (c) the CDFs; (d) invert them to sample.
          </p>
        }
      >
        <Panel className="hemi-figure-panel">
          <Figure
            lobe={lobe}
            kind={kind}
            seed={params.seed}
            n={params.n}
            anim={anim}
            // a link with play=1 and t at its default (the end) plays the animation from the start
            t={
              params.play === true && !prefersReducedMotion() && Number(params.t) >= 1 ? 0 : Number(params.t)
            }
            play={params.play === true}
            setParams={setParams}
            present={mode.present}
            lobeId={lobeId}
            problem={
              inverted ? (
                <Notice kind="warn" testId="figure-no-density">
                  No directions to show: with the identity as printed on the paper, p(θ, φ) = k cot θ e^φ is
                  not a density (its θ-integral diverges; see (b)). Choose &ldquo;sin θ · p(ω)&rdquo; under
                  Jacobian to sample the exam&apos;s lobe.
                </Notice>
              ) : (
                (densityProblem ?? <Notice kind="warn">No valid density to sample yet.</Notice>)
              )
            }
            settings={settings}
          />
        </Panel>
        {isCustom && tab && tab.ok && tab.warning ? (
          <Notice kind="warn">Approximate: {tab.warning}.</Notice>
        ) : null}
        <ExamQ1
          c={checks}
          xi={firstXi}
          invertedShown={inverted}
          onShowInverted={() => setParams({ jacobian: 'inverted' })}
          answer1a={answer1a}
          inverted={<InvertedJacobian />}
          answer1d={answer1d}
          otherLobe={otherLobe}
          mainTestId={lobeId === 'exam'}
        />
      </ExamQuestion>

      <ExamQuestion
        n={2}
        title="Monte Carlo estimators on the hemisphere"
        intro={
          <>
            <p>
              Estimate I = ∫<sub>Ω</sub> f(ω) dω over the upper hemisphere. The exam leaves f open; the scene
              uses the integrand below (default cos θ, whose integral is π) and the same N points (ξ₁, ξ₂) for
              both estimators.
            </p>
            <ExprField
              label="Integrand f(θ, φ)"
              value={params.f}
              onCommit={(s) => setParams({ f: s })}
              error={fc.status === 'error' ? fc.message : null}
              hint="mathjs syntax in theta, phi; the default is cos(theta)"
              testId="f-input"
            />
          </>
        }
      >
        <ExamQ2
          solidAngle={checks.solidAngle}
          lobeTex={lobeTex}
          answer2a={
            <>
              <UniformReadouts
                exact={exact}
                uniform={uniformEst}
                kind={kind}
                rmse={rmse}
                exactProblem={current && fc.status === 'ok' ? current.exactProblem : null}
                exactNote={current?.exactNote}
                fNonFinite={current && fc.status === 'ok' ? current.q2.fNonFinite : 0}
              />
              <StderrNote kind={kind} rmse={rmse} />
            </>
          }
          answer2b={
            <>
              <ImportanceReadouts
                importance={importanceEst}
                importanceOff={importanceOff}
                kind={kind}
                rmse={rmse}
                fNonFinite={current && fc.status === 'ok' ? current.q2.fNonFinite : 0}
                pZero={current && fc.status === 'ok' ? current.q2.pZero : 0}
                infiniteVariance={!!current?.variance?.infinite}
              />
              {lobe && fc.status === 'ok' && current ? (
                <VarianceWarning
                  v={current.variance}
                  lobe={lobeId}
                  exponent={params.exponent}
                  fIsCos={fIsCos}
                />
              ) : null}
              <p className="small">
                Both estimators use the same N points (ξ₁, ξ₂): the uniform one warps them to the hemisphere
                uniformly (p = 1/2π), the importance one with the chosen p
                {baseLobe ? ` (${baseLobe.label})` : ''}. With f = cos θ and the cosine lobe every term f/p
                equals π: zero variance.
              </p>
            </>
          }
          answer2c={repeatSection}
        />
      </ExamQuestion>

      <ExploreFurther intro="Beyond the exam: other sampling densities, the numerical stability of the inversion formulas, and quasi-random point sets (chosen beside the figure).">
        {lobeId !== 'exam' ? (
          <Panel title={`Derivation for the chosen density (${baseLobe ? baseLobe.label : 'typed'})`}>
            <Derivation
              lobe={lobeId}
              exponent={params.exponent}
              custom={customLobe}
              customTex={pc.status === 'ok' ? (pc.tex ?? null) : null}
            />
          </Panel>
        ) : null}
        <Panel title="Numerical stability of the inversion formulas">
          <StabilityDetails />
        </Panel>
      </ExploreFurther>
    </div>
  );
}

interface FigureProps {
  lobe: Lobe | null;
  lobeId: LobeId;
  kind: SequenceKind;
  seed: number;
  n: number;
  anim: AnimKind;
  t: number;
  play: boolean;
  setParams: SceneProps<HemisphereSchema>['setParams'];
  present: boolean;
  problem: React.ReactNode;
  settings: React.ReactNode;
}

/**
 * The figure on the shared timeline. While playing nothing here re-renders per frame: the 3D view
 * is driven directly from the timeline's frames (LiveHemisphereView), the readouts and caption
 * follow a coarse position (FigureText, 4 times a second), the transport writes its own position;
 * the unit square and the settings are memoised. Paused, everything renders the exact position.
 */
function Figure({
  lobe,
  lobeId,
  kind,
  seed,
  n,
  anim,
  t,
  play,
  setParams,
  present,
  problem,
  settings,
}: FigureProps) {
  const box = useRef<HTMLDivElement>(null);
  const tl = useTimeline({
    t,
    play,
    setParams,
    max: 1,
    duration: animDuration(anim, n),
    visibleRef: box,
    renderHz: 0,
  });
  const [showPoints, setShowPoints] = useState(true);
  const [showGrid, setShowGrid] = useState(true);
  const format = (x: number) => {
    const frame = animFrame(lobe, kind, seed, n, anim, x);
    return anim === 'warp'
      ? `t = ${x.toFixed(2)}, s = ${frame.s.toFixed(2)}`
      : `t = ${x.toFixed(2)}: ${formatCount(frame.shown)} of ${formatCount(n)}`;
  };
  return (
    <div className="hemi-figure" ref={box}>
      <div className="hemi-figure-main">
        {lobe ? (
          <LiveHemisphereView
            tl={tl}
            lobe={lobe}
            kind={kind}
            seed={seed}
            n={n}
            anim={anim}
            showPoints={showPoints}
            showGrid={showGrid}
            height={present ? 520 : 400}
          />
        ) : (
          <div className="hemi-no-view">{problem}</div>
        )}
        <TimelineTransport
          timeline={tl}
          label={anim === 'warp' ? 'Warp morph' : 'Samples appearing'}
          format={format}
          testId="timeline"
        >
          <Select
            label="Animation"
            value={anim}
            options={ANIM_OPTIONS}
            onChange={(v) => setParams({ anim: v })}
            testId="anim"
          />
        </TimelineTransport>
        <div className="hemi-toggles">
          <Toggle label="points" checked={showPoints} onChange={setShowPoints} />
          <Toggle label="warped (ξ₁, ξ₂) grid" checked={showGrid} onChange={setShowGrid} />
        </div>
        <FigureText tl={tl} lobe={lobe} lobeId={lobeId} kind={kind} seed={seed} n={n} anim={anim} />
      </div>
      <div className="hemi-figure-side">
        <SquareMemo kind={kind} seed={seed} n={n} size={present ? 260 : 220} />
        {settings}
      </div>
    </div>
  );
}

/** The animation's readouts and caption at a coarse position (4 times a second while playing, exact when paused). */
function FigureText({
  tl,
  lobe,
  lobeId,
  kind,
  seed,
  n,
  anim,
}: {
  tl: Timeline;
  lobe: FigureProps['lobe'];
  lobeId: FigureProps['lobeId'];
  kind: SequenceKind;
  seed: number;
  n: number;
  anim: AnimKind;
}) {
  const t = useCoarsePosition(tl, 4);
  const frame = useMemo(() => animFrame(lobe, kind, seed, n, anim, t), [lobe, kind, seed, n, anim, t]);
  const tr = frame.tracked;
  const spread = lobeId === 'exam' ? examInversion(0, 1 / 8).phiLog1p : null;
  return (
    <>
      <div className="readouts hemi-anim-readouts" data-testid="anim-readouts">
        <Readout id="morph-s" label="morph s = t²(3 − 2t)" value={lobe ? frame.s : null} digits={6} />
        <Readout
          id="anim-count"
          label={anim === 'warp' ? 'points morphing' : 'points drawn at t'}
          value={lobe ? frame.shown : null}
        />
        <Readout id="tracked-x" label="first sample now at x" value={tr ? tr.pos[0] : null} digits={6} />
        <Readout id="tracked-y" label="y" value={tr ? tr.pos[1] : null} digits={6} />
        <Readout id="tracked-z" label="z" value={tr ? tr.pos[2] : null} digits={6} />
      </div>
      <p className="small hemi-caption">
        {anim === 'warp'
          ? 'At t = 0 every point (ξ₁, ξ₂) lies in the unit square drawn flat on the base plane (ξ₁ along x, ξ₂ along y); as t goes to 1 each travels to the direction the inversion of (d) gives it. Each cell of the 8 × 8 grid is a stratum of the square: follow its colour to the patch of the hemisphere it lands on.'
          : 'The samples appear in the order they are drawn, from 1 to N (geometric in t); each keeps the colour of its (ξ₁, ξ₂).'}
        {spread !== null
          ? ` For the exam's lobe, ξ₁ sets θ = arcsin √ξ₁ (rings) and ξ₂ sets φ: the first stratum ξ₂ < 1/8 spreads over φ ∈ [0, ${formatNumber(spread, 3)}) rad, where p ∝ e^φ is small, while the last one is squeezed near φ = 2π.`
          : ''}
        {tr
          ? ` The first sample (ξ₁, ξ₂) = (${formatNumber(tr.xi1, 4)}, ${formatNumber(tr.xi2, 4)}) goes to θ = ${formatNumber(tr.theta, 4)}, φ = ${formatNumber(tr.phi, 4)} (ringed in the square).`
          : ''}
      </p>
    </>
  );
}

/**
 * The 3D view at the timeline's live position: React renders it when its inputs change; every
 * frame the model's frame at t is handed to it directly (HemisphereView's drawRef).
 */
function LiveHemisphereView({
  tl,
  anim,
  ...rest
}: { tl: Timeline; anim: AnimKind } & Omit<ComponentProps<typeof HemisphereView>, 'frame' | 'drawRef'>) {
  const { lobe, kind, seed, n } = rest;
  const drawRef = useRef<((f: AnimFrame) => void) | null>(null);
  const frameAt = (t: number) => animFrame(lobe, kind, seed, n, anim, t);
  const latest = useRef(frameAt);
  latest.current = frameAt;
  useTimelineFrame(tl, (t) => drawRef.current?.(latest.current(t)));
  const t0 = tl.now();
  const frame = useMemo(() => animFrame(lobe, kind, seed, n, anim, t0), [lobe, kind, seed, n, anim, t0]);
  return <HemisphereView {...rest} frame={frame} drawRef={drawRef} />;
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
