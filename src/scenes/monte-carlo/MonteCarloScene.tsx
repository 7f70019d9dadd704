/**
 * Monte Carlo integration and convergence (exam Q2, Q4). All figures come from ./model (pure, over
 * the core) and from the worker jobs in ./jobs; this file only wires parameters to views.
 */
import { useMemo, useState } from 'react';
import type { SceneProps } from '../../app/scene';
import { formatNumber, MathTex, useCompiled, NumberField, Notice, Panel, Readout, SceneLayout, Select, Slider, useShortcuts } from '../../ui';
import { useWorkerJob } from '../../workers';
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
  drawnEstimate,
  exactIntegral,
  keyComparison,
  sampleTable,
  type Fn1,
} from './model';
import { MAX_N, PDF_KINDS, STRATEGIES, type McSchema, type PdfKind, type Strategy } from './params';
import type { McEstimate } from '../../core/estimators';
import type { ProblemArgs } from './jobs';
import { compileX, compileXFast } from './expr';
import { FunctionPlot } from './view/FunctionPlot';
import { ConvergencePanel } from './view/ConvergencePanel';
import { RmsePanel } from './view/RmsePanel';
import { HistogramPanel } from './view/HistogramPanel';
import { WorkedTable } from './view/WorkedTable';
import { SamplesField, FnField } from './view/Fields';
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

const makeWorker = () => new Worker(new URL('./mc.worker.ts', import.meta.url), { type: 'module' });

export default function MonteCarloScene({ params, setParams, mode }: SceneProps<McSchema>) {
  const pdfKind = (PDF_KINDS as readonly string[]).includes(params.pdf) ? (params.pdf as PdfKind) : 'uniform';
  const seq = (STRATEGIES as readonly string[]).includes(params.strategy) ? (params.strategy as Strategy) : 'independent';

  // --- the integrand (typed; falls back to the exam's f with a message) -----------------------
  const fc = useCompiled(params.f, compileX, { fast: compileXFast });
  const fFallback = useCompiled(EXAM_F, compileX, { fast: compileXFast });
  const fOk = fc.status === 'ok';
  const fSrc = fOk ? params.f : EXAM_F;
  const f: Fn1 | null = fc.status === 'ok' ? fc.fn : fc.status === 'error' && fFallback.status === 'ok' ? fFallback.fn : null;
  const fError = fc.status === 'error' ? fc.message : null;

  const lim = checkLimits(params.a, params.b);
  const { a, b } = lim;

  const pc = useCompiled(params.pdfexpr, compileX, { enabled: pdfKind === 'custom', fast: compileXFast });
  const pdfExprError = pdfKind === 'custom' && pc.status === 'error' ? pc.message : null;
  const customFn = pdfKind === 'custom' && pc.status === 'ok' ? pc.fn : null;

  const exact = useMemo(() => (f ? exactIntegral(fSrc, f, a, b) : null), [f, fSrc, a, b]);
  const choice = useMemo(() => {
    if (!f) return null;
    if (pdfKind === 'custom' && pc.status !== 'ok') return pc.status === 'pending' ? null : ({ ok: false, kind: 'custom', message: `The pdf expression is not valid: ${pdfExprError}` } as const);
    return choosePdf(pdfKind, fSrc, f, a, b, customFn);
  }, [f, fSrc, a, b, pdfKind, customFn, pc.status, pdfExprError]);
  const propChoice = useMemo(() => (f ? choosePdf('proportional', fSrc, f, a, b, null) : null), [f, fSrc, a, b]);

  // --- the worked table: given samples, or the exam's four ------------------------------------
  const given = params.samples && params.samples.length ? params.samples : null;
  const tableXs = given ?? EXAM_SAMPLES;
  const table = useMemo(() => {
    if (!f) return null;
    const dens = choice && choice.ok ? choice.density : null;
    const prop = propChoice && propChoice.ok ? propChoice.density : null;
    return sampleTable(tableXs, f, a, b, dens, prop);
  }, [f, a, b, choice, propChoice, tableXs]);
  const keyNotes = useMemo(() => (table ? keyComparison(fSrc, a, b, tableXs, table) : []), [table, fSrc, a, b, tableXs]);

  // --- the estimate: given samples → exactly these; else n drawn samples ----------------------
  const n = Math.max(1, Math.min(MAX_N, Math.round(params.n)));
  const syncEstimate = useMemo<McEstimate | null>(() => {
    if (given || !f || !choice || !choice.ok || n > SYNC_MAX_N) return null;
    return drawnEstimate(f, choice.sampler, seq, params.seed, n);
  }, [given, f, choice, seq, params.seed, n]);
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
  const bigArgs = baseArgs ? { ...baseArgs, strategies: [{ pdf: pdfKind, seq, label: 'selected' }], n } : null;
  const bigTask = useWorkerJob<McEstimate & { ms: number }>(makeWorker, 'estimate', bigArgs, { key: bigKey, enabled: !!bigKey && !!baseArgs });

  const chosenOk = !!choice && choice.ok;
  const est: McEstimate | null = given ? (chosenOk && table?.chosen && table.chosen.invalid === 0 ? table.chosen : null) : needBig ? (bigTask.result ?? null) : syncEstimate;
  const estValue = est && est.invalid === 0 ? est.estimate : null;
  const stderrValue = est && est.invalid === 0 && Number.isFinite(est.stderr) ? est.stderr : null;

  const curve = useMemo(() => (f ? curves(f, choice && choice.ok ? choice.density : null, a, b) : null), [f, choice, a, b]);

  const [runToken, setRunToken] = useState(0);
  useShortcuts({
    playPause: () => setRunToken((t) => t + 1),
    step: () => setParams({ seed: (params.seed + 1) >>> 0 }),
    reset: () => setParams({ f: EXAM_F, a: EXAM_A, b: EXAM_B, pdf: 'uniform', strategy: 'independent', samples: null, seed: 1 }),
  });

  const controls = (
    <>
      <Panel title="Integral">
        <FnField label="f(x) =" value={params.f} error={fError ? `${fError} — using ${EXAM_F}` : null} onCommit={(s) => setParams({ f: s })} testId="f-input" />
        <div className="mc-limits">
          <NumberField label="a" value={params.a} min={-1000} max={1000} step={0.5} onChange={(v) => setParams({ a: v })} testId="a-input" />
          <NumberField label="b" value={params.b} min={-1000} max={1000} step={0.5} onChange={(v) => setParams({ b: v })} testId="b-input" />
        </div>
        {lim.message ? <Notice kind="warn">{lim.message}</Notice> : null}
      </Panel>
      <Panel title="Sampling">
        <Select label="pdf p(x)" value={pdfKind} options={PDF_OPTIONS} onChange={(v) => setParams({ pdf: v })} testId="pdf-select" />
        {pdfKind === 'custom' ? (
          <FnField label="p(x) ∝" value={params.pdfexpr} error={pdfExprError} onCommit={(s) => setParams({ pdfexpr: s })} testId="pdfexpr-input" hint="any positive multiple; normalized numerically" />
        ) : null}
        <Select label="sequence" value={seq} options={SEQ_OPTIONS} onChange={(v) => setParams({ strategy: v })} testId="strategy-select" />
        <Slider label="samples N" value={n} min={1} max={MAX_N} step={1} log onChange={(v) => setParams({ n: Math.round(v) })} digits={8} testId="n-slider" />
        <NumberField label="seed" value={params.seed} min={0} max={4294967295} step={1} onChange={(v) => setParams({ seed: Math.round(v) })} testId="seed-input" />
        <SamplesField value={params.samples} onCommit={(s) => setParams({ samples: s })} />
      </Panel>
    </>
  );

  const main = (
    <>
      {choice && !choice.ok ? (
        <Notice kind="error" testId="pdf-error">
          {choice.message}
        </Notice>
      ) : null}
      <Panel title="The integral and the pdf">
        <div className="readouts">
          <Readout id="exact" label="exact ∫ f dx" value={exact?.value ?? null} digits={12} note={exact ? (exact.problem ?? exact.method) : 'compiling f…'} />
          <Readout id="estimate" label={given ? `estimate from the ${given.length} given samples` : `estimate, N = ${n.toLocaleString('en')}`} value={estValue} digits={10} />
          <Readout id="stderr" label="standard error s/√N" value={stderrValue} digits={4} />
          <Readout id="abs-error" label="|estimate − exact|" value={estValue !== null && exact && Number.isFinite(exact.value) ? Math.abs(estValue - exact.value) : null} digits={3} />
        </div>
        {needBig && bigTask.running ? (
          <p className="mc-progress" role="status">
            Estimating with {n.toLocaleString('en')} samples in a worker… {Math.round(bigTask.progress * 100)} %{' '}
            <button type="button" onClick={bigTask.cancel}>
              Cancel
            </button>
          </p>
        ) : null}
        {needBig && bigTask.result ? <p className="mc-note">{n.toLocaleString('en')} samples took {formatNumber(bigTask.result.ms, 3)} ms in the worker.</p> : null}
        {needBig && bigTask.error ? <Notice kind="error">The run failed: {bigTask.error}</Notice> : null}
        {est && est.invalid > 0 ? (
          <Notice kind="error">
            {est.invalid} of the samples have p = 0 where f ≠ 0 (or f is not finite there): no estimate is shown, because it would be biased.
          </Notice>
        ) : null}
        {choice && choice.ok ? (
          <p className="mc-pdf-label">
            {choice.label}
            {choice.note ? <span className="mc-note"> {choice.note}</span> : null}
          </p>
        ) : null}
        {curve && f ? <FunctionPlot curve={curve} samples={table ? table.rows.map((r) => [r.x, r.f] as [number, number]) : []} a={a} b={b} /> : null}
        <div className="mc-math">
          <MathTex
            display
            tex={String.raw`\begin{gathered}\langle I\rangle = \frac{1}{N}\sum_{i=1}^{N}\frac{f(x_i)}{p(x_i)},\quad x_i\sim p \\ \operatorname{SE} = \frac{s}{\sqrt N} \\ s^2 = \frac{1}{N-1}\sum_{i=1}^{N}\Big(\frac{f(x_i)}{p(x_i)} - \langle I\rangle\Big)^2\end{gathered}`}
          />
        </div>
      </Panel>
      {table && f ? (
        <WorkedTable table={table} keyNotes={keyNotes} given={!!given} pdfOk={chosenOk} pdfKind={pdfKind} a={a} b={b} onUseExam={() => setParams({ samples: [...EXAM_SAMPLES] })} onDraw={() => setParams({ samples: null })} />
      ) : null}
      {baseArgs ? (
        <>
          <ConvergencePanel args={baseArgs} nMax={n} exact={exact?.value ?? NaN} makeWorker={makeWorker} present={mode.present} runToken={runToken} />
          <RmsePanel args={baseArgs} nMax={Math.min(n, 100_000)} runs={params.runs} exact={exact?.value ?? NaN} makeWorker={makeWorker} onRuns={(r) => setParams({ runs: r })} />
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
    </>
  );

  return <SceneLayout controls={controls} main={main} />;
}
