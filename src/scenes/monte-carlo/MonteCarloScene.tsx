/**
 * Monte Carlo integration and convergence (exam Q2, Q4). All figures come from ./model (pure, over
 * the core) and from the worker jobs in ./jobs; this file only wires parameters to views.
 */
import { formatCount } from '../../ui/format';
import { useCallback, useMemo } from 'react';
import type { SceneProps } from '../../kit/scene';
import {
  ExamQuestion,
  ExploreFurther,
  formatNumber,
  MathTex,
  useCompiled,
  NumberField,
  Notice,
  Panel,
  Readout,
  SceneLayout,
  Select,
  Slider,
} from '../../ui';
import { useWorkerJob, workerFactory } from '../../workers';
import type { McTasks } from './mc.worker';
import {
  EXAM_A,
  EXAM_B,
  EXAM_F,
  EXAM_SAMPLES,
  SYNC_MAX_N,
  checkLimits,
  choosePdf,
  comparedStrategies,
  curves,
  drawnProblem,
  exactIntegral,
  keyComparison,
  roundTo,
  RACE_MAX,
  sampleTable,
  squareShift,
  stderrIsValid,
  type Fn1,
} from './model';
import { MAX_N, PDF_KINDS, STRATEGIES, type McSchema, type PdfKind, type Strategy } from './params';
import type { McEstimate, Problem1D } from '../../core/estimators';
import type { ProblemArgs } from './jobs';
import { compileX, compileXFast } from './expr';
import { FunctionPlot } from './view/FunctionPlot';
import { ConvergencePanel } from './view/ConvergencePanel';
import { RmsePanel } from './view/RmsePanel';
import { HistogramPanel } from './view/HistogramPanel';
import { KeyFigures, SampleRows } from './view/WorkedTable';
import { RaceSection, Q4dRace, type RaceInput } from './view/RaceSection';
import { Q4a, Q4b, Q4c } from './view/ExamQ4';
import { SamplesField, FnField } from './view/Fields';
import { useSlicedEstimate } from './view/hooks';
import './monte-carlo.css';

const PDF_OPTIONS: { value: PdfKind; label: string }[] = [
  { value: 'uniform', label: 'uniform, p = 1/(b − a)' },
  { value: 'linear', label: 'linear ramp through |f(a)|, |f(b)|' },
  { value: 'proportional', label: 'proportional to f' },
  { value: 'custom', label: 'custom (type p(x))' },
];
const SEQ_OPTIONS: { value: Strategy; label: string }[] = [
  { value: 'independent', label: 'independent (i.i.d.)' },
  { value: 'stratified', label: 'stratified (jittered)' },
  { value: 'halton', label: 'Halton (Owen-scrambled)' },
  { value: 'sobol', label: 'Sobol (Owen-scrambled)' },
];

const makeWorker = workerFactory<McTasks>(
  () => new Worker(new URL('./mc.worker.ts', import.meta.url), { type: 'module' }),
);

export default function MonteCarloScene({ params, setParams, mode }: SceneProps<McSchema>) {
  const pdfKind = (PDF_KINDS as readonly string[]).includes(params.pdf) ? (params.pdf as PdfKind) : 'uniform';
  const seq = (STRATEGIES as readonly string[]).includes(params.strategy)
    ? (params.strategy as Strategy)
    : 'independent';

  // --- the integrand (typed; falls back to the exam's f with a message) -----------------------
  const fc = useCompiled(params.f, compileX, { fast: compileXFast });
  const fFallback = useCompiled(EXAM_F, compileX, { fast: compileXFast });
  const fOk = fc.status === 'ok';
  const fSrc = fOk ? params.f : EXAM_F;
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
        : ({
            ok: false,
            kind: 'custom',
            message: `The pdf expression is not valid: ${pdfExprError}`,
          } as const);
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
  // numbers as model.drawnEstimate, without one long task on load (issue 15)
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
  const bigKey = needBig ? `${fSrc}|${a}|${b}|${pdfKind}|${params.pdfexpr}|${seq}|${params.seed}|${n}` : '';
  const bigArgs = baseArgs
    ? { ...baseArgs, strategies: [{ pdf: pdfKind, seq, label: 'selected' }], n }
    : null;
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
  const estValue = est && est.invalid === 0 ? est.estimate : null;
  const stderrValue = est && est.invalid === 0 && Number.isFinite(est.stderr) ? est.stderr : null;

  const curve = useMemo(
    () => (f ? curves(f, choice && choice.ok ? choice.density : null, a, b) : null),
    [f, choice, a, b],
  );

  // --- the animation: uniform against importance on the same ξᵢ (model.raceTrack / raceAt) -------
  const raceImp =
    choice && choice.ok && choice.kind !== 'uniform'
      ? choice
      : propChoice && propChoice.ok
        ? propChoice
        : null;
  // the track itself is computed by the race's components (./view/RaceSection), not in this render
  const raceInput = useMemo<RaceInput | null>(
    () =>
      f && raceImp && exact && Number.isFinite(exact.value)
        ? {
            f,
            a,
            b,
            sampler: raceImp.sampler,
            density: raceImp.density,
            exact: exact.value,
            seed: params.seed,
          }
        : null,
    [f, raceImp, exact, a, b, params.seed],
  );
  const importanceLabel = raceImp
    ? raceImp.kind === 'proportional'
      ? raceImp.label.replace(/ \(closed form.*\)$/, '').replace(/^/, 'p ∝ f: ')
      : raceImp.label
    : '';
  const setRace = useCallback((patch: { t?: number; play?: boolean }) => setParams(patch), [setParams]);

  // --- s/√N is no error estimate for stratified / QMC points: RMSE over randomized runs instead ---
  const qmc = !given && !stderrIsValid(seq) && chosenOk && !!baseArgs;
  const rmseN = Math.min(n, 100_000);
  const rmseTask = useWorkerJob(
    makeWorker,
    'rmse',
    qmc && baseArgs
      ? {
          ...baseArgs,
          strategies: [{ pdf: pdfKind, seq, label: 'selected' }],
          nMax: rmseN,
          runs: params.runs,
        }
      : null,
    {
      key: qmc
        ? `${fSrc}|${a}|${b}|${pdfKind}|${params.pdfexpr}|${seq}|${params.seed}|${rmseN}|${params.runs}`
        : '',
      enabled: qmc,
      delayMs: 250,
      queue: 'monte-carlo',
    },
  );
  const rmseAtN = (() => {
    const r = rmseTask.result?.rmse[0];
    if (!r || r.n.length === 0) return null;
    const k = r.n.length - 1;
    return r.n[k] === rmseN ? r.rmse[k] : null;
  })();

  const sq = squareShift(fSrc);
  const examSq = sq !== null;
  const isExamConfig =
    sq === 2 &&
    a === EXAM_A &&
    b === EXAM_B &&
    tableXs.length === EXAM_SAMPLES.length &&
    tableXs.every((x, i) => x === EXAM_SAMPLES[i]);

  const controls = (
    <>
      <Panel title="Integral">
        <FnField
          label="f(x) ="
          value={params.f}
          error={fError ? `${fError} — using ${EXAM_F}` : null}
          onCommit={(s) => setParams({ f: s })}
          testId="f-input"
        />
        <div className="mc-limits">
          <NumberField
            label="a"
            value={params.a}
            min={-1000}
            max={1000}
            step={0.5}
            onChange={(v) => setParams({ a: v })}
            testId="a-input"
          />
          <NumberField
            label="b"
            value={params.b}
            min={-1000}
            max={1000}
            step={0.5}
            onChange={(v) => setParams({ b: v })}
            testId="b-input"
          />
        </div>
        {lim.message ? <Notice kind="warn">{lim.message}</Notice> : null}
      </Panel>
      <Panel title="Sampling">
        <Select
          label="pdf p(x)"
          value={pdfKind}
          options={PDF_OPTIONS}
          onChange={(v) => setParams({ pdf: v })}
          testId="pdf-select"
        />
        {pdfKind === 'custom' ? (
          <FnField
            label="p(x) ∝"
            value={params.pdfexpr}
            error={pdfExprError}
            onCommit={(s) => setParams({ pdfexpr: s })}
            testId="pdfexpr-input"
            hint="any positive multiple; normalized numerically"
          />
        ) : null}
        <Select
          label="sequence"
          value={seq}
          options={SEQ_OPTIONS}
          onChange={(v) => setParams({ strategy: v })}
          testId="strategy-select"
        />
        <Slider
          label="samples N"
          value={n}
          min={1}
          max={MAX_N}
          step={1}
          log
          onChange={(v) => setParams({ n: Math.round(v) })}
          digits={8}
          testId="n-slider"
        />
        <NumberField
          label="seed"
          value={params.seed}
          min={0}
          max={4294967295}
          step={1}
          onChange={(v) => setParams({ seed: Math.round(v) })}
          testId="seed-input"
        />
        <SamplesField value={params.samples} onCommit={(s) => setParams({ samples: s })} />
      </Panel>
    </>
  );

  const c = sq ?? 2;
  const ca = examSq ? a : EXAM_A;
  const cb = examSq ? b : EXAM_B;
  const exactReadout = (
    <Readout
      id="exact"
      label="exact ∫ f dx"
      value={exact?.value ?? null}
      digits={12}
      note={exact ? (exact.problem ?? exact.method) : 'compiling f…'}
    />
  );
  const givenNotFromP = given && chosenOk && pdfKind !== 'uniform';
  const estimateBlock = (
    <>
      <div className="readouts">
        <Readout
          id="estimate"
          label={
            given ? `estimate from the ${given.length} given samples` : `estimate, N = ${formatCount(n)}`
          }
          value={estValue}
          digits={10}
        />
        <Readout
          id="stderr"
          label={qmc ? 's/√N (not an error estimate for these points)' : 'standard error s/√N'}
          value={stderrValue}
          digits={4}
        />
        <Readout
          id="abs-error"
          label="|estimate − exact|"
          value={
            estValue !== null && exact && Number.isFinite(exact.value)
              ? Math.abs(estValue - exact.value)
              : null
          }
          digits={3}
        />
        {qmc ? (
          <Readout
            id="rmse-at-n"
            label={`RMSE over ${params.runs} randomized runs, N = ${formatCount(rmseN)}`}
            value={rmseAtN}
            digits={4}
            note={
              rmseTask.running
                ? `running… ${Math.round(rmseTask.progress * 100)} %`
                : rmseTask.error
                  ? `failed: ${rmseTask.error.message}`
                  : undefined
            }
          />
        ) : null}
      </div>
      {qmc ? (
        <Notice kind="warn" testId="stderr-not-error">
          {seq === 'stratified' ? 'Stratified (jittered)' : seq === 'halton' ? 'Halton' : 'Sobol'} points are
          not independent, so the standard error s/√N is not an error estimate for them (it treats the points
          as i.i.d. and usually overstates the error by far). The error of this method is measured instead as
          the RMSE over {params.runs} independently randomized runs
          {rmseN < n ? ` (at N = ${formatCount(rmseN)})` : ''}.
        </Notice>
      ) : null}
      {givenNotFromP ? (
        <Notice kind="warn" testId="given-not-from-p">
          These samples were typed in, not drawn from{' '}
          {choice && choice.ok ? choice.label.replace(/ \(.*\)$/, '') : 'p'}. The estimator (1/N) Σ
          f(xᵢ)/p(xᵢ) is unbiased only for xᵢ drawn from p; with given samples the numbers above are only
          arithmetic on them
          {pdfKind === 'proportional' ? ' (for p ∝ f every term still equals ∫ f dx, whatever the xᵢ)' : ''},
          and s/√N is not an error estimate.
        </Notice>
      ) : null}
      {needBig && bigTask.running ? (
        <p className="mc-progress" role="status">
          Estimating with {formatCount(n)} samples in a worker… {Math.round(bigTask.progress * 100)} %{' '}
          <button type="button" onClick={bigTask.cancel}>
            Cancel
          </button>
        </p>
      ) : null}
      {needBig && bigTask.result ? (
        <p className="mc-note">
          {formatCount(n)} samples took {formatNumber(bigTask.result.ms, 3)} ms in the worker.
        </p>
      ) : null}
      {needBig && bigTask.error ? (
        <Notice kind="error">The run failed: {bigTask.error.message}</Notice>
      ) : null}
      {est && est.invalid > 0 ? (
        <Notice kind="error">
          {est.invalid} of the samples have p = 0 where f ≠ 0 (or f is not finite there): no estimate is
          shown, because it would be biased.
        </Notice>
      ) : null}
    </>
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
        title="Monte Carlo integration in 1D"
        intro={
          <>
            <p>
              I = ∫₀² (x + 2)² dx: (a) analytically, (b) uniform Monte Carlo, (c) importance sampling, (d)
              convergence.
              {!isExamConfig ? (
                <>
                  {' '}
                  <span className="mc-note" data-testid="not-exam-config">
                    Your settings differ from the exam’s; the numbers below are for yours.{' '}
                    <button
                      type="button"
                      onClick={() =>
                        setParams({ f: EXAM_F, a: EXAM_A, b: EXAM_B, samples: [...EXAM_SAMPLES] })
                      }
                    >
                      Exam configuration
                    </button>
                  </span>
                </>
              ) : null}
            </p>
            <RaceSection
              input={raceInput}
              importanceLabel={importanceLabel}
              t={Number(params.t)}
              play={params.play === true}
              setParams={setRace}
              fallback={
                <p className="mc-note">The animation needs a finite integral and a usable importance pdf.</p>
              }
            />
          </>
        }
      >
        <Q4a c={c} a={ca} b={cb} isSquare={examSq} exact={exactReadout} />
        {table && f ? (
          <Q4b
            table={table}
            c={sq}
            a={a}
            b={b}
            headline={
              <>
                <div className="readouts mc-headline">
                  <Readout
                    id="q4-uniform"
                    label="uniform ⟨I⟩ = (b − a)/N Σ f(xᵢ)"
                    value={table.uniform.invalid ? null : table.uniform.estimate}
                    digits={6}
                    note={
                      table.uniform.invalid
                        ? undefined
                        : `to 2 decimals, as the exam writes it: ${roundTo(table.uniform.estimate, 2).toFixed(2)}`
                    }
                  />
                </div>
                <SampleRows table={table} pdfOk={chosenOk} pdfKind={pdfKind} />
                <div className="mc-buttons">
                  {given ? (
                    <button type="button" onClick={() => setParams({ samples: null })}>
                      Draw N samples instead
                    </button>
                  ) : (
                    <button type="button" onClick={() => setParams({ samples: [...EXAM_SAMPLES] })}>
                      Use these four samples for the estimate
                    </button>
                  )}
                </div>
                <h5 className="mc-subhead">
                  With the page’s settings (
                  {given ? 'the given samples' : `N = ${formatCount(n)} drawn samples`}, pdf {pdfKind}, {seq})
                </h5>
                {estimateBlock}
              </>
            }
            keyFigures={<KeyFigures keyNotes={keyNotes} a={a} b={b} />}
          />
        ) : null}
        {table && f ? (
          <Q4c
            table={table}
            c={c}
            a={ca}
            b={cb}
            isSquare={examSq}
            answer={
              <div className="readouts mc-headline">
                <Readout
                  id="q4-importance"
                  label="importance ⟨I⟩ with p ∝ f"
                  value={
                    table.proportional && !table.proportional.invalid ? table.proportional.estimate : null
                  }
                  digits={10}
                  note={
                    table.proportional && table.proportional.n > 1
                      ? `spread of f/p: s = ${formatNumber(Math.sqrt(table.proportional.variance), 3)} (zero variance)`
                      : undefined
                  }
                />
              </div>
            }
          />
        ) : null}
        <Q4dRace
          input={raceInput}
          importanceIsExam={raceImp?.kind === 'proportional'}
          onWhole={() => setParams({ t: RACE_MAX, play: false })}
        />
      </ExamQuestion>
      <ExploreFurther intro="Other integrands and pdfs, stratified and quasi-Monte Carlo points, many runs, run time, and unbiasedness (exam Q2 c).">
        <Panel title="The integrand and the pdf">
          {choice && choice.ok ? (
            <p className="mc-pdf-label">
              {choice.label}
              {choice.note ? <span className="mc-note"> {choice.note}</span> : null}
            </p>
          ) : null}
          {curve && f ? (
            <FunctionPlot
              curve={curve}
              samples={table ? table.rows.map((r) => [r.x, r.f] as [number, number]) : []}
              a={a}
              b={b}
            />
          ) : null}
          <div
            className="mc-math"
            tabIndex={0}
            role="group"
            aria-label="formulas (scroll sideways when wider than the screen)"
          >
            <MathTex
              display
              tex={String.raw`\begin{gathered}\langle I\rangle = \frac{1}{N}\sum_{i=1}^{N}\frac{f(x_i)}{p(x_i)},\quad x_i\sim p \\ \operatorname{SE} = \frac{s}{\sqrt N}\ \text{(independent } x_i \text{ only)} \\ s^2 = \frac{1}{N-1}\sum_{i=1}^{N}\Big(\frac{f(x_i)}{p(x_i)} - \langle I\rangle\Big)^2\end{gathered}`}
            />
          </div>
        </Panel>
        {baseArgs ? (
          <>
            <ConvergencePanel
              args={baseArgs}
              nMax={n}
              exact={exact?.value ?? NaN}
              makeWorker={makeWorker}
              present={mode.present}
            />
            <RmsePanel
              args={baseArgs}
              nMax={Math.min(n, 100_000)}
              runs={params.runs}
              exact={exact?.value ?? NaN}
              makeWorker={makeWorker}
              onRuns={(r) => setParams({ runs: r })}
            />
            {chosenOk ? (
              <HistogramPanel
                args={{ ...baseArgs, strategies: [{ pdf: pdfKind, seq, label: 'selected' }] }}
                N={params.hn}
                exact={exact?.value ?? NaN}
                makeWorker={makeWorker}
                onN={(v) => setParams({ hn: v })}
              />
            ) : null}
          </>
        ) : null}
      </ExploreFurther>
    </>
  );

  return <SceneLayout controls={controls} main={main} />;
}
