/**
 * Monte Carlo integration and convergence (exam Q2, Q4). All figures come from the scene's pure
 * modules (over the core) and from the worker jobs in ./jobs; this file only wires parameters to views.
 */
import { useCallback, useMemo } from 'react';
import type { SceneProps } from '../../kit/scene';
import { ExamQuestion, useCompiled, Notice, SceneLayout } from '../../ui';
import { useWorkerJob } from '../../workers';
import { makeWorker } from './worker';
import { EXAM_F, EXAM_SAMPLES, isExamConfig, keyComparison } from './exam';
import { EXAM_A, EXAM_B } from './integral';
import { SYNC_MAX_N, drawnProblem, stderrIsValid } from './drawnEstimate';
import { checkLimits, exactIntegral, squareShift, type Fn1 } from './integral';
import { choosePdf, importanceLane } from './pdfChoice';
import { comparedStrategies } from './compared';
import { RACE_MAX } from './race';
import { sampleTable } from './sampleTable';
import { MAX_N, type McSchema } from './params';
import type { McEstimate, Problem1D } from '../../core/estimators';
import { rmseAt, type ProblemArgs } from './jobs';
import { fail } from '../../core/failure';
import { compileX, compileXFast } from './expr';
import { McExplore } from './view/Explore';
import { raceInputOf, RaceSection } from './view/RaceSection';
import { McControls } from './view/Controls';
import { EstimateBlock } from './view/EstimateBlock';
import { useHeldAtStart, useSlicedEstimate } from './view/hooks';
import { Q4Intro } from './exam/Q4';
import { Q4a } from './exam/Q4a';
import { Q4b } from './exam/Q4b';
import { Q4c } from './exam/Q4c';
import { Q4d } from './exam/Q4d';
import './monte-carlo.css';

export default function MonteCarloScene({ params, setParams, mode }: SceneProps<McSchema>) {
  const pdfKind = params.pdf;
  const seq = params.strategy;

  // --- the integrand (typed; falls back to the exam's f with a message) -----------------------
  const fc = useCompiled(params.f, compileX, { fast: compileXFast });
  const fFallback = useCompiled(EXAM_F, compileX, { fast: compileXFast });
  const fSrc = fc.status === 'ok' ? params.f : EXAM_F;
  const f: Fn1 | null =
    fc.status === 'ok' ? fc.fn : fc.status === 'error' && fFallback.status === 'ok' ? fFallback.fn : null;
  const fError = fc.status === 'error' ? fc.message : null;

  const lim = checkLimits(params.a, params.b);
  const { a, b } = lim;

  const pc = useCompiled(params.pdfexpr, compileX, { enabled: pdfKind === 'custom', fast: compileXFast });
  const pdfExprError = pdfKind === 'custom' && pc.status === 'error' ? pc.message : null;
  const customFn = pdfKind === 'custom' && pc.status === 'ok' ? pc.fn : null;

  const exact = useMemo(() => (f ? exactIntegral(fSrc, f, a, b) : null), [f, fSrc, a, b]);
  const choice = useMemo(() => {
    if (!f) return null;
    if (pdfKind === 'custom' && pc.status !== 'ok')
      return pc.status === 'pending'
        ? null
        : fail('custom', `The pdf expression is not valid: ${pdfExprError}`);
    return choosePdf(pdfKind, fSrc, f, a, b, customFn);
  }, [f, fSrc, a, b, pdfKind, customFn, pc.status, pdfExprError]);
  const propChoice = useMemo(
    () => (f ? choosePdf('proportional', fSrc, f, a, b, null) : null),
    [f, fSrc, a, b],
  );

  // --- the worked table: given samples, or the exam's four ------------------------------------
  const given = params.samples && params.samples.length ? params.samples : null;
  const tableXs = given ?? EXAM_SAMPLES;
  const table = useMemo(() => {
    if (!f) return null;
    const dens = choice && choice.ok ? choice.density : null;
    const prop = propChoice && propChoice.ok ? propChoice.density : null;
    return sampleTable(tableXs, f, a, b, dens, prop);
  }, [f, a, b, choice, propChoice, tableXs]);
  const keyNotes = useMemo(
    () => (table ? keyComparison(fSrc, a, b, tableXs, table) : []),
    [table, fSrc, a, b, tableXs],
  );

  // --- the estimate: given samples → exactly these; else n drawn samples ----------------------
  const n = Math.max(1, Math.min(MAX_N, Math.round(params.n)));
  // drawn on the main thread (n ≤ SYNC_MAX_N) in short tasks after the first render: the same
  // numbers as model.drawnEstimate, without one long task on load
  const syncProblem = useMemo<Problem1D | null>(() => {
    if (given || !f || !choice || !choice.ok || n > SYNC_MAX_N) return null;
    return drawnProblem(f, choice.sampler, seq, params.seed);
  }, [given, f, choice, seq, params.seed, n]);
  const syncEstimate = useSlicedEstimate(syncProblem, n);
  const needBig = !given && !!f && !!choice && choice.ok && n > SYNC_MAX_N;
  const baseArgs: ProblemArgs | null = useMemo(
    () =>
      f && choice
        ? {
            f: fSrc,
            a,
            b,
            pdfexpr: params.pdfexpr,
            seed: params.seed,
            strategies: comparedStrategies(pdfKind, seq, choice.ok),
          }
        : null,
    [f, choice, fSrc, a, b, params.pdfexpr, params.seed, pdfKind, seq],
  );
  // the selected strategy alone, and the identity of a run of it (a new key restarts the worker job)
  const selected = [{ pdf: pdfKind, seq, label: 'selected' }];
  const runKey = `${fSrc}|${a}|${b}|${pdfKind}|${params.pdfexpr}|${seq}|${params.seed}`;
  const bigKey = needBig ? `${runKey}|${n}` : '';
  const bigArgs = baseArgs ? { ...baseArgs, strategies: selected, n } : null;
  const bigTask = useWorkerJob(makeWorker, 'estimate', bigArgs, {
    key: bigKey,
    enabled: !!bigKey && !!baseArgs,
  });

  const chosenOk = !!choice && choice.ok;
  const est: McEstimate | null = given
    ? chosenOk && table?.chosen && table.chosen.invalid === 0
      ? table.chosen
      : null
    : needBig
      ? (bigTask.result ?? null)
      : syncEstimate;

  // --- the animation: uniform against importance on the same ξᵢ (model.raceTrack / raceAt) -------
  const lane = importanceLane(choice, propChoice);
  const raceImp = lane?.pdf ?? null;
  // the track itself is computed by the race's components (./view/RaceSection), not in this render
  const raceInput = useMemo(
    () => raceInputOf(f, raceImp, exact, a, b, params.seed),
    [f, raceImp, exact, a, b, params.seed],
  );
  const setRace = useCallback((patch: { t?: number; play?: boolean }) => setParams(patch), [setParams]);
  // ask=1: the race holds at its start (t = 0 in the link, so it is still there when revealed)
  const held = mode.ask;
  useHeldAtStart(held, params.t, params.play, setRace);
  const race = (
    <RaceSection
      input={raceInput}
      importanceLabel={lane?.label ?? ''}
      importanceName={lane?.name ?? ''}
      t={held ? 0 : Number(params.t)}
      play={!held && params.play === true}
      setParams={setRace}
      staged={mode.present}
      held={held}
    />
  );

  // --- s/√N is no error estimate for stratified / QMC points: RMSE over randomized runs instead ---
  const qmc = !given && !stderrIsValid(seq) && chosenOk && !!baseArgs;
  const rmseN = Math.min(n, 100_000);
  const rmseTask = useWorkerJob(
    makeWorker,
    'rmse',
    qmc && baseArgs ? { ...baseArgs, strategies: selected, nMax: rmseN, runs: params.runs } : null,
    { key: qmc ? `${runKey}|${rmseN}|${params.runs}` : '', enabled: qmc, delayMs: 250, queue: 'monte-carlo' },
  );
  const rmseAtN = rmseAt(rmseTask.result?.rmse, rmseN);

  const sq = squareShift(fSrc);
  const examSq = sq !== null;
  const examConfig = isExamConfig(sq, a, b, tableXs);

  const controls = (
    <McControls
      params={params}
      setParams={setParams}
      fError={fError}
      limitsMessage={lim.message}
      pdfExprError={pdfExprError}
    />
  );

  const c = sq ?? 2;
  const ca = examSq ? a : EXAM_A;
  const cb = examSq ? b : EXAM_B;
  const estimateBlock = (
    <EstimateBlock
      given={given ? given.length : null}
      n={n}
      est={est}
      exact={exact?.value ?? null}
      rmse={qmc ? { seq, runs: params.runs, n: rmseN, value: rmseAtN, task: rmseTask } : null}
      notFromP={given && choice?.ok && pdfKind !== 'uniform' ? choice.label.replace(/ \(.*\)$/, '') : null}
      pdfKind={pdfKind}
      big={needBig ? { task: bigTask, ms: bigTask.result?.ms ?? null } : null}
    />
  );

  const main = (
    <>
      {choice && !choice.ok ? (
        <Notice kind="error" testId="pdf-error">
          {choice.message}
        </Notice>
      ) : null}
      <ExamQuestion
        n={4}
        intro={
          <Q4Intro
            isExamConfig={examConfig}
            onExamConfig={setParams}
            race={mode.present ? null : race}
            input={raceInput}
            t={held ? 0 : Number(params.t)}
            exact={exact}
            table={table}
            ask={held}
          />
        }
      >
        <Q4a c={c} a={ca} b={cb} isSquare={examSq} exact={exact} ask={held} />
        {table && f ? (
          <Q4b
            table={table}
            c={sq}
            a={a}
            b={b}
            given={!!given}
            pdfOk={chosenOk}
            pdfKind={pdfKind}
            seq={seq}
            n={n}
            keyNotes={keyNotes}
            onSamples={(samples) => setParams({ samples })}
            estimate={estimateBlock}
            ask={held}
          />
        ) : null}
        {table && f ? <Q4c table={table} c={c} a={ca} b={cb} isSquare={examSq} ask={held} /> : null}
        <Q4d
          input={raceInput}
          importanceIsExam={raceImp?.kind === 'proportional'}
          onWhole={() => setParams({ t: RACE_MAX, play: false })}
          ask={held}
        />
      </ExamQuestion>
      <McExplore
        integrand={{ choice, f, table, a, b }}
        baseArgs={baseArgs}
        selected={selected}
        n={n}
        runs={params.runs}
        hn={params.hn}
        exact={exact?.value ?? NaN}
        makeWorker={makeWorker}
        present={mode.present}
        ask={held}
        setParams={setParams}
      />
    </>
  );

  return <SceneLayout controls={controls} main={main} stage={mode.present ? race : undefined} />;
}
