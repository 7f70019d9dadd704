/**
 * Scene `#/hemisphere` (exam Q1, Q2), exam first: the question as the exam states it, part by part,
 * each with its written derivation (live numbers) and its live answer; then "Explore further" (other
 * lobes' derivations, floating-point stability, float32 on a GPU), each a fold. The figure that
 * teaches Q1 — the warp morph of the unit square onto the hemisphere, on the shared timeline — sits
 * right after the question, with only N beside it (the other settings are folded). Samples, χ² and
 * the Q2 estimators are computed in a worker.
 */
import { useMemo, type ReactNode } from 'react';
import type { SceneProps } from '../../kit/scene';
import { useCompiled, ExprField, Notice, MathTex, formatNumber, keepTextParenthesesTogether } from '../../ui';
import { Fold } from '../../ui/Fold';
import { ExamQuestion, ExploreFurther } from '../../ui/exam';
import { useWorkerJob } from '../../workers';
import { makeWorker } from './worker';
import { nextTask } from '../../ui/chunked';
import { fillSequence2D } from '../../core/random';
import { examChecksCached } from './examChecks';
import { lobeFromParams } from './lobe';
import type { HemisphereSchema } from './params';
import { compileThetaPhi, compileThetaPhiFast, isCosTheta } from './expr';
import { Derivation } from './view/Derivation';
import { ImportanceReadouts, StderrNote, UniformReadouts, VarianceWarning } from './view/Q2Panel';
import { InvertedJacobian } from './view/InvertedJacobian';
import { GpuWarpSection } from './view/GpuWarpSection';
import { Q1Figure, type DensityProblem } from './view/Q1Figure';
import { Settings } from './view/Settings';
import { SampleCheck } from './view/SampleCheck';
import { CdfPlots } from './view/CdfPlots';
import { RepeatSection } from './view/RepeatSection';
import { StabilityDetails } from './view/StabilityDetails';
import { Q1 } from './exam/Q1';
import { Q2, lobeTexOf } from './exam/Q2';
import type { RepeatArgs, StatsArgs } from './jobs';
import './hemisphere.css';

const REPEAT_RUNS = 1000;

// The exam's quadrature checks (a few ms of adaptive 2D integration) in a task of their own as the
// scene's code arrives, not inside its first render; the render reads the cached result.
nextTask(() => void examChecksCached());

export default function HemisphereScene(props: SceneProps<HemisphereSchema>) {
  const { params, setParams, mode } = props;
  const lobeId = params.lobe;
  const kind = params.points;
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

  // ---- readouts -------------------------------------------------------------------------------
  const k = baseLobe ? baseLobe.k : null;
  const exact = current && Number.isFinite(current.exact) ? current.exact : null;
  const uniformEst = current && fc.status === 'ok' ? current.q2.uniform : null;
  const importanceEst = current && fc.status === 'ok' && lobe ? current.q2.importance : null;
  const importanceOff = inverted
    ? "off: the paper's identity gives no density to sample"
    : !lobe
      ? 'off: no valid density to sample'
      : null;
  const rmse = current && fc.status === 'ok' ? current.rmse : null;
  // what both estimators' error notes depend on: the point set, the measured RMSE, f's bad samples
  const errorBasis = { kind, rmse, fNonFinite: current && fc.status === 'ok' ? current.q2.fNonFinite : 0 };

  const checks = useMemo(() => examChecksCached(), []);
  const firstXi = useMemo(() => {
    if (params.n < 1) return null;
    const u = new Float64Array(2);
    fillSequence2D(kind, params.seed, params.n, u, 0, 1, 0);
    return { xi1: u[0], xi2: u[1] };
  }, [kind, params.seed, params.n]);

  const densityProblem: DensityProblem | null =
    isCustom && pc.status === 'error'
      ? { what: 'The typed density could not be used', message: pc.message }
      : isCustom && tab && !tab.ok
        ? { what: 'This is not a valid density', message: tab.message }
        : null;

  const pdfError = pc.status === 'error' ? pc.message : tab && !tab.ok ? tab.message : null;
  const settings = (more: ReactNode) => (
    <Settings
      params={params}
      setParams={setParams}
      pdfError={pdfError}
      stats={stats}
      folded={!mode.present}
      more={more}
    />
  );

  const otherLobe =
    lobeId !== 'exam' ? (
      <Notice kind="info" testId="other-lobe">
        The figure, the checks in (d) and the estimates of Q2 use the chosen density,{' '}
        {baseLobe ? baseLobe.label : 'the typed density'}
        {baseLobe ? (
          <>
            , whose k ={' '}
            <output data-testid="k-chosen" data-value={String(baseLobe.k)}>
              {formatNumber(baseLobe.k, baseLobe.kDigits)}
            </output>{' '}
            ({baseLobe.kSource}, {baseLobe.kDigits} significant digits)
          </>
        ) : null}
        ; the derivation above and its k are the exam&apos;s, for k cos θ e<sup>φ</sup>. The chosen
        density&apos;s own derivation is folded under Explore further.
      </Notice>
    ) : null;

  const figure = (
    <Q1Figure {...props} lobe={lobe} densityProblem={densityProblem} chi2={current?.chi2 ?? null}>
      {settings}
    </Q1Figure>
  );
  const lobeTex = lobeTexOf(
    lobeId,
    params.exponent,
    k,
    pc.status === 'ok' ? (pc.tex ?? null) : null,
    baseLobe?.kDigits,
  );
  return (
    // classroom mode: the stage first (`stage-layout` lets the shell compact the heading above it)
    <div className={mode.present ? 'hemi-page stage-layout' : 'hemi-page'}>
      {mode.present ? figure : null}
      <ExamQuestion
        n={1}
        intro={
          <p>
            <MathTex tex={`p(\\omega) = k\\cos\\theta\\,e^{\\phi}`} /> on the upper hemisphere (θ ∈ [0, π/2]
            from the normal +z, φ ∈ [0, 2π) from +x): (a) normalize it; (b) change variables, find the
            marginals; (c) the CDFs; (d) invert them to sample.
          </p>
        }
      >
        {mode.present ? null : figure}
        {isCustom && tab && tab.ok && tab.warning ? (
          <Notice kind="warn">Approximate: {tab.warning}.</Notice>
        ) : null}
        <Q1
          c={checks}
          xi={firstXi}
          invertedShown={inverted}
          onShowInverted={() => setParams({ jacobian: 'inverted' })}
          inverted={<InvertedJacobian />}
          answer1d={
            <SampleCheck current={current} lobe={lobe} inverted={inverted} kind={kind} n={params.n} />
          }
          cdfs={lobe ? <CdfPlots lobe={lobe} stats={current} xi={firstXi} /> : null}
          otherLobe={otherLobe}
          mainTestId={lobeId === 'exam'}
          ask={mode.ask}
        />
      </ExamQuestion>

      <ExamQuestion
        n={2}
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
        <Q2
          solidAngle={checks.solidAngle}
          lobeTex={lobeTex}
          ask={mode.ask}
          answer2a={
            <>
              <UniformReadouts
                {...errorBasis}
                exact={exact}
                uniform={uniformEst}
                exactProblem={current && fc.status === 'ok' ? current.exactProblem : null}
                exactNote={current?.exactNote}
              />
              <StderrNote kind={kind} rmse={rmse} />
            </>
          }
          answer2b={
            <>
              <ImportanceReadouts
                {...errorBasis}
                importance={importanceEst}
                importanceOff={importanceOff}
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
                uniformly {keepTextParenthesesTogether('(p = 1/2π)')}, the importance one with the chosen p
                {baseLobe ? ` (${baseLobe.label})` : ''}. With f = cos θ and the cosine lobe every term f/p
                equals π: zero variance.
              </p>
            </>
          }
          answer2c={
            <RepeatSection repeat={repeat} fOk={fc.status === 'ok'} exact={exact} args={repeatArgs} />
          }
        />
      </ExamQuestion>

      <ExploreFurther intro="Beyond the exam: other sampling densities (chosen under More settings), the numerical stability of the inversion formulas, and the warps in float32 on a GPU. Each opens on its own.">
        {lobeId !== 'exam' ? (
          <Fold
            name="lobe-derivation"
            summary={`The derivation for the chosen density, ${baseLobe ? baseLobe.label : 'the typed density'}: normalize, marginals, CDFs, inversion`}
          >
            <Derivation
              lobe={lobeId}
              exponent={params.exponent}
              custom={customLobe}
              customTex={pc.status === 'ok' ? (pc.tex ?? null) : null}
            />
          </Fold>
        ) : null}
        <StabilityDetails />
        <GpuWarpSection seed={params.seed} />
      </ExploreFurther>
    </div>
  );
}
