/**
 * Solid angle and area lights (exam Q6): dω = dA cos θ_l / r² drawn, the rendering equation over
 * solid angle and over area, and three estimators of the light reflected by a Lambertian floor —
 * uniform area (the key's), solid-angle (spherical rectangle) and cosine hemisphere sampling —
 * against the analytic reference (Lambert's formula). All figures come from ./model over the core.
 */
import {
  memo,
  useCallback,
  useEffect,
  useMemo,
  useRef,
  useState,
  type ComponentProps,
  type ReactNode,
  type RefObject,
} from 'react';
import type { SceneProps } from '../../kit/scene';
import {
  Derivation,
  ExamPart,
  ExamQuestion,
  ExploreFurther,
  KeyNote,
  LiveAnswer,
  MathTex,
  Notice,
  NumberField,
  Panel,
  Plot,
  Readout,
  SceneLayout,
  Select,
  Slider,
  TEXT_HZ,
  TimelineTransport,
  Toggle,
  useSeenOnce,
  useTimeline,
  useTimelineFrame,
  type Timeline,
} from '../../ui';
import type { PlotTrace } from '../../ui';
import { useWorkerJob, workerFactory } from '../../workers';
import type { AreaLightTasks } from './floor.worker';
import { runChunked } from '../../ui/chunked';
import type { LightStrategy } from '../../core/lights';
import {
  STRATEGIES,
  STRATEGY_LABEL,
  STRATEGY_SHORT,
  animationFrame,
  animationLength,
  buildModel,
  estimateOne,
  givenSamples,
  patchModel,
  sampleRun,
  targetValue,
  type AreaLightModel,
  type StrategyEstimate,
} from './model';
import { floorJob, floorPassAt } from './floor';
import { PRESETS, schema, type AreaLightParams } from './params';
import { RunningEstimate } from './view/RunningEstimate';
import { Scene3D } from './view/Scene3D';
import { FloorImages } from './view/FloorImages';
import { PatchFigure } from './view/PatchFigure';
import './area-light.css';

type Schema = typeof schema;

/** Largest n per strategy estimated on the main thread. */
const SYNC_MAX = 65536;
const COLORS: Record<LightStrategy, string> = {
  area: '#b34700',
  'solid-angle': '#1f5fa8',
  cosine: '#1d7a3a',
};
const makeWorker = workerFactory<AreaLightTasks>(
  () => new Worker(new URL('./floor.worker.ts', import.meta.url), { type: 'module' }),
);

const LEGEND_TOP = { orientation: 'h', x: 0, y: 1.02, yanchor: 'bottom' };

const fmt = (x: number, d = 4) => (Number.isFinite(x) ? Number(x.toPrecision(d)).toString() : '—');

/** Highlight colours of Q6(b)'s boxes (Jacobian, visibility): light boxes with dark text, or dark boxes with light text. */
function highlight(dark: boolean) {
  return dark
    ? { jBg: '#5c3412', jFg: '#fde2c8', vBg: '#1e4628', vFg: '#d7ecd9' }
    : { jBg: '#fde2c8', jFg: '#1c1d21', vBg: '#d7ecd9', vFg: '#1c1d21' };
}

export default function AreaLightScene({ params, setParams, mode }: SceneProps<Schema>) {
  const set = useCallback((patch: Partial<AreaLightParams>) => setParams(patch), [setParams]);
  const model = useMemo(() => buildModel(params), [params]);
  const strategy = params.strategy as LightStrategy;
  const n = params.n;
  const seed = params.seed;

  // Up to SYNC_MAX samples per strategy the estimates are computed here (a few ms); beyond, in a
  // worker, so a slider drag never blocks the page. Same seeds and streams: the same numbers.
  // The chosen strategy's (Q6(c)'s answer) in that answer's render (<Answer6c>: it mounts with
  // its exam part, not in the page's first render); the table's three in tasks after it, one
  // strategy per task (issue 15: all three in the first render were one long task on a phone,
  // cold code at 4× CPU slowdown).
  const big = n > SYNC_MAX;
  // what the estimates depend on (the model object is rebuilt on any parameter change, t included)
  const timingKey = JSON.stringify([
    model.p,
    model.lc,
    model.w,
    model.h,
    model.tilt,
    model.L,
    model.rho,
    model.occluder ? 1 : 0,
    seed,
  ]);
  const [later, setLater] = useState<{ key: string; list: StrategyEstimate[] } | null>(null);
  const estKey = `${timingKey}|${n}`;
  const latestModel = useRef(model);
  latestModel.current = model;
  useEffect(() => {
    if (big) return;
    const m = latestModel.current;
    const list: StrategyEstimate[] = [];
    const cancels = STRATEGIES.map((s) =>
      runChunked(() => {
        list.push(estimateOne(m, s, n, seed));
        if (list.length === STRATEGIES.length) setLater({ key: estKey, list });
      }),
    );
    return () => cancels.forEach((c) => c());
  }, [big, estKey, n, seed]);
  const estTask = useWorkerJob(makeWorker, 'estimates', params, {
    enabled: big,
    delayMs: 150,
  });
  /** The table's estimates, null until they are computed. */
  const estimates: StrategyEstimate[] | null = big
    ? (estTask.result ?? null)
    : later?.key === estKey
      ? later.list
      : null;
  const pending = big && !estTask.result;
  const target = targetValue(model);
  const patch = useMemo(
    () => patchModel(model, params.pu, params.pv, params.psize, params.ptilt),
    [model, params.pu, params.pv, params.psize, params.ptilt],
  );
  // Convergence series (3 × 32768 samples) in the worker: ~0.1 s that a slider drag should not wait for.
  // The convergence and timing runs start when their panels come near the screen (not on load:
  // their results re-render the scene while the first screen should be answering input).
  const convBox = useRef<HTMLDivElement>(null);
  const timingBox = useRef<HTMLDivElement>(null);
  const convSeen = useSeenOnce(convBox);
  const timingSeen = useSeenOnce(timingBox);
  const convArgs = useMemo(() => ({ params, nMax: 1 << 15 }), [params]);
  const convTask = useWorkerJob(makeWorker, 'convergence', convArgs, {
    key: timingKey,
    delayMs: 120,
    enabled: convSeen,
  });
  const conv = convTask.result;

  const job = useMemo(() => floorJob(model, seed), [model, seed]);

  const timing = useWorkerJob(makeWorker, 'timing', params, {
    key: timingKey,
    delayMs: 400,
    enabled: timingSeen,
  });

  // The animation (issue 12): t = samples of the chosen strategy arrived so far, 0 … min(n, 1024).
  const animMax = animationLength(n);
  const stageRef = useRef<HTMLDivElement>(null);
  const tl = useTimeline({
    t: Number(params.t),
    play: !!params.play,
    setParams: setParams as (p: { t?: number; play?: boolean }) => void,
    max: animMax,
    integer: true,
    duration: Math.max(4, animMax / 64),
    visibleRef: stageRef,
    // while playing, the scene (readouts, floor pass) re-renders 4 times a second; the 3D samples
    // and the running-estimate plot follow every frame by direct writes (LiveScene3D, LiveRunning)
    renderHz: 4,
  });
  const floorPass = floorPassAt(tl.t, animMax);

  // "Reseed every second": a new seed each second, to watch the estimate jitter within its error bar.
  const [reseeding, setReseeding] = useState(false);
  useEffect(() => {
    if (!reseeding) return;
    const t = setInterval(() => setParams({ seed: (Date.now() >>> 0) % 4294967295 }), 1000);
    return () => clearInterval(t);
  }, [reseeding, setParams]);

  const dark = mode.theme === 'dark';
  const vpHeight = mode.present ? 480 : 380;

  const convTraces: PlotTrace[] = useMemo(() => {
    const out: PlotTrace[] = [];
    for (const c of conv ?? []) {
      out.push({
        x: Array.from(c.n),
        y: Array.from(c.absError),
        type: 'scatter',
        mode: 'lines',
        name: STRATEGY_SHORT[c.strategy],
        legendgroup: c.strategy,
        line: { color: COLORS[c.strategy], width: 2 },
      });
      out.push({
        x: Array.from(c.n),
        y: Array.from(c.stderr),
        type: 'scatter',
        mode: 'lines',
        name: `std. error, ${STRATEGY_SHORT[c.strategy]}`,
        legendgroup: c.strategy,
        showlegend: false,
        line: { color: COLORS[c.strategy], dash: 'dot', width: 1.5 },
      });
    }
    return out;
  }, [conv]);
  const timingTraces: PlotTrace[] = useMemo(() => {
    const pts = timing.result ?? [];
    return STRATEGIES.map((s) => {
      // Sorted by run time, so the path never doubles back in x (a busy machine can time a larger N faster).
      const rows = pts
        .filter((r) => r.strategy === s && r.rmse > 0 && r.seconds > 0)
        .sort((a, b) => a.seconds - b.seconds);
      return {
        x: rows.map((r) => r.seconds * 1e3),
        y: rows.map((r) => r.rmse),
        text: rows.map((r) => `N = ${r.n}`),
        type: 'scatter',
        mode: 'lines+markers',
        name: STRATEGY_SHORT[s],
        line: { color: COLORS[s] },
      };
    });
  }, [timing.result]);

  const vec = useCallback(
    (label: string, key: 'p' | 'lc', v: [number, number, number]) => (
      <fieldset className="al-vec">
        <legend>{label}</legend>
        {(['x', 'y', 'z'] as const).map((axis, k) => (
          <NumberField
            key={axis}
            label={axis}
            value={v[k]}
            step={0.1}
            min={-1e9}
            max={1e9}
            testId={`${key}-${axis}`}
            onChange={(x) => {
              const nv: [number, number, number] = [...v];
              nv[k] = x;
              set({ [key]: nv } as Partial<AreaLightParams>);
            }}
          />
        ))}
      </fieldset>
    ),
    [set],
  );

  // Everything below is memoised on the parameters (not on t), so an animation frame re-renders
  // only the stage's animated bits and the floor images' pass choice.
  const controls = useMemo(
    () => (
      <>
        <Panel title="Presets">
          <div className="al-presets" role="group" aria-label="Presets">
            {PRESETS.map((pr) => (
              <button
                key={pr.id}
                type="button"
                title={pr.what}
                onClick={() => set({ ...pr.params })}
                data-testid={`preset-${pr.id}`}
              >
                {pr.label}
              </button>
            ))}
          </div>
        </Panel>
        <Panel title="Sampling">
          <Select
            label="Strategy"
            value={strategy}
            options={STRATEGIES.map((s) => ({ value: s, label: STRATEGY_LABEL[s] }))}
            onChange={(s) => set({ strategy: s })}
            testId="strategy"
          />
          <Slider
            label="Samples n"
            value={n}
            min={1}
            max={1000000}
            step={1}
            log
            onChange={(x) => set({ n: Math.round(x) })}
          />
          <NumberField
            label="Seed"
            value={seed}
            min={0}
            max={4294967295}
            step={1}
            onChange={(x) => set({ seed: Math.round(x) })}
          />
          <div className="al-row">
            <button type="button" onClick={() => set({ seed: (seed + 1) >>> 0 })}>
              New seed
            </button>
            <button type="button" aria-pressed={reseeding} onClick={() => setReseeding((p) => !p)}>
              {reseeding ? '❚❚ Stop reseeding' : '↻ Reseed every second'}
            </button>
          </div>
        </Panel>
        <Panel title="Light and floor">
          {vec('Light centre', 'lc', params.lc)}
          <Slider
            label="Width w"
            value={params.ls?.[0] ?? 1}
            min={0}
            max={10}
            step={0.05}
            onChange={(x) => set({ ls: [x, params.ls?.[1] ?? 1] })}
          />
          <Slider
            label="Height h"
            value={params.ls?.[1] ?? 1}
            min={0}
            max={10}
            step={0.05}
            onChange={(x) => set({ ls: [params.ls?.[0] ?? 1, x] })}
          />
          <Slider
            label="Tilt about x"
            value={params.tilt}
            min={-180}
            max={180}
            step={1}
            unit="°"
            onChange={(x) => set({ tilt: x })}
          />
          <Slider
            label="Radiance L"
            value={params.L}
            min={0}
            max={10}
            step={0.1}
            onChange={(x) => set({ L: x })}
          />
          <Slider
            label="Albedo ρ"
            value={params.rho}
            min={0}
            max={1}
            step={0.01}
            onChange={(x) => set({ rho: x })}
          />
          {vec('Shading point p (normal +z)', 'p', params.p)}
          <Toggle
            label="Occluder between point and light"
            checked={params.occluder}
            onChange={(b) => set({ occluder: b })}
          />
        </Panel>
      </>
    ),
    [params, strategy, n, seed, reseeding, set, vec],
  );

  const answer6c = useMemo(
    () => (
      <Answer6c
        model={model}
        strategy={strategy}
        n={n}
        seed={seed}
        big={big}
        estimates={estimates}
        pending={pending}
        target={target}
      />
    ),
    [model, strategy, n, seed, big, estimates, pending, target],
  );

  // the exam parts' JSX in a component of its own (memoised on its props, as the memo it replaces):
  // React can yield between the scene's render and its (issue 15)
  const exam = (
    <Q6Parts
      patch={patch}
      pu={params.pu}
      pv={params.pv}
      psize={params.psize}
      ptilt={params.ptilt}
      model={model}
      seed={seed}
      dark={dark}
      set={set}
      answer6c={answer6c}
    />
  );

  const explore = useMemo(
    () => (
      <>
        <Panel title="Three strategies for the same integral">
          <p>
            Solid-angle sampling draws ω uniformly over the light’s spherical rectangle (pdf 1/Ω), so each
            term is Ω f L V cos θ; cosine sampling draws ω with pdf cos θ / π, so each term is ρ L V when the
            ray hits the light and 0 when it misses. All three are unbiased; they differ in variance. All
            samples are independent pseudo-random draws, so the standard error s/√N is a valid error estimate
            for each.
          </p>
          <table className="al-table">
            <caption>
              All three strategies, n = {n} each, seed {seed}
            </caption>
            <thead>
              <tr>
                <th scope="col">strategy</th>
                <th scope="col">estimate</th>
                <th scope="col">std. error σ</th>
                <th scope="col">(est. − ref.)/σ</th>
              </tr>
            </thead>
            <tbody>
              {estimates === null ? (
                <tr>
                  <td colSpan={4}>
                    <progress aria-label="Estimating the three strategies" /> Estimating…
                  </td>
                </tr>
              ) : null}
              {(estimates ?? []).map((e) => (
                <tr key={e.strategy} className={e.strategy === strategy ? 'al-current' : undefined}>
                  <th scope="row" title={STRATEGY_LABEL[e.strategy]}>
                    {STRATEGY_SHORT[e.strategy]}
                  </th>
                  <td>
                    <Readout id={`estimate-${e.strategy}`} label="" value={e.estimate} digits={5} />
                  </td>
                  <td>
                    <Readout id={`stderr-${e.strategy}`} label="" value={e.stderr} digits={2} />
                  </td>
                  <td>
                    {e.stderr > 0 && Number.isFinite(target) ? fmt((e.estimate - target) / e.stderr, 3) : '—'}
                  </td>
                </tr>
              ))}
            </tbody>
          </table>
        </Panel>
        <Panel title="Convergence">
          <div ref={convBox} />
          <Plot
            ariaLabel="Absolute error and standard error of the three estimators against the number of samples, log-log."
            data={convTraces}
            height={mode.present ? 380 : 300}
            layout={{
              xaxis: { type: 'log', title: { text: 'N (samples)' } },
              yaxis: { type: 'log', title: { text: 'error' } },
              legend: LEGEND_TOP,
              margin: { l: 56, r: 16, t: 40, b: 44 },
            }}
          />
          <p className="al-note">
            Solid: |estimate − reference|. Dotted: the standard error s/√N the estimator reports. Both fall
            like N^−½; the strategies differ by a constant.
          </p>
        </Panel>
        <Panel title="Run time against error">
          <div ref={timingBox} className="al-progress-slot">
            {timing.running ? (
              <progress max={1} value={timing.progress} aria-label="Timing progress" />
            ) : null}
          </div>
          {timing.error ? <Notice kind="warn">Timing failed: {timing.error.message}</Notice> : null}
          <Plot
            ariaLabel="RMSE over independent runs against the run time of one estimate, for the three strategies, log-log."
            data={timingTraces}
            height={mode.present ? 360 : 280}
            layout={{
              xaxis: { type: 'log', title: { text: 'time per estimate (ms)' } },
              yaxis: { type: 'log', title: { text: 'RMSE' } },
              legend: LEGEND_TOP,
              margin: { l: 56, r: 16, t: 40, b: 44 },
            }}
          />
          <p className="al-note">
            Each point: N = 16 … 4096 samples, RMSE over 24 independent runs, run time measured in a worker on
            this machine (best of three; noisy when the machine is busy). Points are joined in order of run
            time, so the line never doubles back. Lower-left wins.
          </p>
        </Panel>
      </>
    ),
    [
      estimates,
      strategy,
      n,
      seed,
      target,
      convTraces,
      timingTraces,
      timing.running,
      timing.progress,
      timing.error,
      mode.present,
    ],
  );

  const stage = (
    <Stage
      tl={tl}
      stageRef={stageRef}
      model={model}
      strategy={strategy}
      animMax={animMax}
      seed={seed}
      patch={patch}
      vpHeight={vpHeight}
      dark={dark}
      target={target}
    />
  );

  const main = (
    <>
      {model.messages.map((m, i) => (
        <Notice key={i} kind={m.kind} testId={`al-message-${i}`}>
          {m.text}
        </Notice>
      ))}
      <ExamQuestion
        n={6}
        title="Solid angle and area lights"
        intro={
          <p>
            A rectangular area light of radiance L shines on a floor point x (normal +z, Lambertian, albedo
            ρ). (a) Derive dω = dA cos θ_l / r² by similar triangles; (b) write the rendering equation over
            the light’s area; (c) give the Monte Carlo estimator with uniform area sampling.
          </p>
        }
      >
        {stage}
        {exam}
      </ExamQuestion>
      <ExploreFurther intro="Beyond the exam: two other ways to sample the same integral, how fast each converges, what it costs, and what its noise looks like on a whole floor.">
        {explore}
        <Panel title="The floor, rendered with each strategy">
          <FloorImages job={job} pass={floorPass} />
          <p className="al-note">
            {job.size} × {job.size} pixels of floor, {fmt(2 * job.half, 3)} units across, all at the same
            samples per pixel, which grow with the timeline (at its end: 64). The light’s footprint is
            brightest; the grain is each strategy’s variance.
          </p>
        </Panel>
      </ExploreFurther>
    </>
  );

  return <SceneLayout controls={controls} main={main} />;
}

/** The 3D view with the samples arrived at the timeline's live position (drawn per frame without a React render). */
function LiveScene3D({
  tl,
  run,
  ...rest
}: { tl: Timeline; run: ComponentProps<typeof RunningEstimate>['run'] } & Omit<
  ComponentProps<typeof Scene3D>,
  'count' | 'countRef'
>) {
  const countRef = useRef<((k: number) => void) | null>(null);
  const latest = useRef(run);
  latest.current = run;
  useTimelineFrame(tl, (t) => countRef.current?.(animationFrame(latest.current, t).k));
  return <Scene3D {...rest} count={animationFrame(run, tl.now()).k} countRef={countRef} />;
}

/** The running-estimate plot at the timeline's live position (drawn per frame without a React render; its label ≤ TEXT_HZ). */
function LiveRunning({
  tl,
  run,
  reference,
}: {
  tl: Timeline;
  run: ComponentProps<typeof RunningEstimate>['run'];
  reference: number;
}) {
  const drawRef = useRef<((k: number, text: boolean) => void) | null>(null);
  const latest = useRef(run);
  latest.current = run;
  const lastText = useRef(-Infinity);
  useTimelineFrame(tl, (t, playing) => {
    const now = performance.now();
    const text = !playing || now - lastText.current >= 1000 / TEXT_HZ - 1;
    if (text) lastText.current = now;
    drawRef.current?.(animationFrame(latest.current, t).k, text);
  });
  return (
    <RunningEstimate run={run} reference={reference} k={animationFrame(run, tl.now()).k} drawRef={drawRef} />
  );
}

/**
 * Q6(c)'s live answer: the chosen strategy's estimate with n samples (on the main thread up to
 * SYNC_MAX, else from the worker's list), its standard error and the verdict against the reference.
 */
const Answer6c = memo(function Answer6c({
  model,
  strategy,
  n,
  seed,
  big,
  estimates,
  pending,
  target,
}: {
  model: AreaLightModel;
  strategy: LightStrategy;
  n: number;
  seed: number;
  big: boolean;
  estimates: StrategyEstimate[] | null;
  pending: boolean;
  target: number;
}) {
  const chosenSync = useMemo(
    () => (big ? null : estimateOne(model, strategy, n, seed)),
    [big, model, strategy, n, seed],
  );
  const chosen: StrategyEstimate = chosenSync ??
    estimates?.find((e) => e.strategy === strategy) ?? { strategy, estimate: NaN, stderr: NaN, n };
  const zTarget =
    Number.isFinite(target) && chosen.stderr > 0 ? (chosen.estimate - target) / chosen.stderr : null;
  return (
    <LiveAnswer testId="answer-6c">
      <div className="al-readouts">
        <Readout
          id="estimate"
          label={`estimate, ${STRATEGY_LABEL[strategy]}, n = ${n}`}
          value={chosen.estimate}
          digits={7}
        />
        <Readout id="stderr" label="standard error" value={chosen.stderr} digits={3} />
        <Readout
          id="reference-6c"
          label={model.occluder ? 'reference (with occluder)' : 'reference (Lambert)'}
          value={Number.isFinite(target) ? target : null}
          digits={7}
        />
      </div>
      <p className="al-verdict" data-testid="al-verdict">
        {pending ? (
          <>
            <progress aria-label="Estimating" /> Estimating with n = {n} samples per strategy in the
            background…
          </>
        ) : zTarget === null ? (
          chosen.stderr === 0 && chosen.estimate === target ? (
            'Every sample gave the same value: the estimate is exact here.'
          ) : (
            'No standard error yet (n < 2), or no analytic value to compare with.'
          )
        ) : (
          `The estimate is ${fmt(Math.abs(zTarget), 2)} standard errors ${zTarget >= 0 ? 'above' : 'below'} the ${model.occluder ? 'occluded ' : ''}reference${Math.abs(zTarget) <= 3 ? ' — within 3σ, as an unbiased estimator should be (about 997 times in 1000).' : ' — outside 3σ (happens about 3 times in 1000 for a correct estimator; try another seed).'}`
        )}
      </p>
    </LiveAnswer>
  );
});

/**
 * The animated stage: the 3D view with the samples arrived so far, the transport, the running
 * estimate and its readouts. Its own component, so that its sample run is computed in a render
 * of its own (React can yield between it and the scene's: issue 15).
 */
function Stage({
  tl,
  stageRef,
  model,
  strategy,
  animMax,
  seed,
  patch,
  vpHeight,
  dark,
  target,
}: {
  tl: Timeline;
  stageRef: RefObject<HTMLDivElement | null>;
  model: AreaLightModel;
  strategy: LightStrategy;
  animMax: number;
  seed: number;
  patch: ComponentProps<typeof Scene3D>['patch'];
  vpHeight: number;
  dark: boolean;
  target: number;
}) {
  const run = useMemo(() => sampleRun(model, strategy, animMax, seed), [model, strategy, animMax, seed]);
  const af = animationFrame(run, tl.t);
  const fmtPos = useCallback((t: number) => `${Math.floor(t)} of ${animMax} samples`, [animMax]);
  return (
    <div className="al-stage-wrap">
      <div className="al-stage" ref={stageRef}>
        <div className="al-stage-3d">
          <LiveScene3D
            tl={tl}
            run={run}
            model={model}
            strategy={strategy}
            samples={run.points}
            terms={run.terms}
            patch={patch}
            height={vpHeight}
            dark={dark}
          />
        </div>
        <div className="al-stage-side">
          <TimelineTransport
            timeline={tl}
            label={`Samples arriving (${STRATEGY_SHORT[strategy]})`}
            format={fmtPos}
          />
          <div className="al-readouts al-anim-readouts">
            <Readout id="anim-k" label="samples arrived k" value={af.k} digits={7} />
            <Readout
              id="anim-estimate"
              label={`running estimate, ${STRATEGY_SHORT[strategy]}`}
              value={af.k > 0 ? af.estimate : null}
              digits={7}
            />
            <Readout
              id="anim-stderr"
              label="its standard error"
              value={af.k > 1 ? af.stderr : null}
              digits={3}
            />
            <Readout
              id="anim-term"
              label="newest sample’s term"
              value={af.k > 0 ? af.newestTerm : null}
              digits={5}
            />
          </div>
          <LiveRunning tl={tl} run={run} reference={target} />
        </div>
        <p className="al-legend">
          Yellow: the emitting side of the light (its back is dark). Dots: the samples of the{' '}
          {STRATEGY_LABEL[strategy]} strategy arrived so far
          {strategy === 'cosine'
            ? ', as directions on the unit hemisphere'
            : ' on the light, and their directions on the unit hemisphere'}{' '}
          — green where the sample contributes, red where it is wasted (below the horizon, blocked, or missing
          the light); lines to the newest. Orange: the Q6(a) patch and its projection on the unit sphere. The
          small plot (beside the view, or below it on narrow screens): the running estimate with ±2 standard
          errors, converging on the reference (dashed).
        </p>
      </div>
    </div>
  );
}

/** Q6's three exam parts (the question and, mounted late by ExamPart, their bodies). */
const Q6Parts = memo(function Q6Parts({
  patch,
  pu,
  pv,
  psize,
  ptilt,
  model,
  seed,
  dark,
  set,
  answer6c,
}: {
  patch: ReturnType<typeof patchModel>;
  pu: number;
  pv: number;
  psize: number;
  ptilt: number;
  model: AreaLightModel;
  seed: number;
  dark: boolean;
  set: (patch: Partial<AreaLightParams>) => void;
  answer6c: ReactNode;
}) {
  const hl = useMemo(() => highlight(dark), [dark]);
  const given = useMemo(() => givenSamples(model, seed, 4), [model, seed]);
  const fArea = given.f;
  const patchTraces: PlotTrace[] = useMemo(
    () => [
      {
        x: Array.from(patch.series.side),
        y: Array.from(patch.series.relError),
        type: 'scatter',
        mode: 'lines',
        name: '|dA cos θ_l / r² − Ω| / Ω',
        line: { color: '#e4572e' },
      },
      {
        x: [patch.side],
        y: [Math.abs(patch.relError)],
        type: 'scatter',
        mode: 'markers',
        name: 'this patch',
        marker: { color: '#e4572e', size: 10 },
      },
    ],
    [patch],
  );
  return (
    <>
      <ExamPart
        id="6a"
        title="Solid angle of a small area element"
        asks={
          <>
            A small area element dA of a light, at distance r from x, arbitrarily oriented (normal n_l at
            angle θ_l to the direction back to x), subtends a solid angle dω. Show that{' '}
            <MathTex tex={String.raw`d\omega = \dfrac{dA\cos\theta_l}{r^2}`} />.
          </>
        }
      >
        <Derivation testId="derivation-6a">
          <ol className="al-steps">
            <li>
              Project dA onto the plane perpendicular to the ray: a perpendicular element{' '}
              <MathTex tex={String.raw`dA^{\perp}`} /> with sides dl, so{' '}
              <MathTex tex={String.raw`dA^{\perp} = dl\cdot dl = dA\cos\theta_l`} />
              <span className="al-live" data-testid="step-6a-perp">
                {' '}
                (here dA = {fmt(patch.area)}, cos θ_l = {fmt(patch.cosThetaL)}, dA⊥ ={' '}
                {fmt(patch.area * patch.cosThetaL)}, dl = {fmt(Math.sqrt(patch.area * patch.cosThetaL))})
              </span>
              .
            </li>
            <li>
              The solid-angle element is the patch dA⊥ casts on the unit sphere, with sides dω_l:{' '}
              <MathTex tex={String.raw`d\omega = d\omega_l\cdot d\omega_l`} />.
            </li>
            <li>
              By similar triangles (shaded in the figure: legs 1 and dω_l/2 on the unit circle, legs r and
              dl/2 at the patch):{' '}
              <MathTex
                tex={String.raw`\frac{d\omega_l/2}{1} = \frac{dl/2}{r}\;\Rightarrow\; d\omega_l = \frac{dl}{r}`}
              />
              <span className="al-live" data-testid="step-6a-similar">
                {' '}
                (r = {fmt(patch.r)}: dω_l = {fmt(Math.sqrt(patch.area * patch.cosThetaL) / patch.r)})
              </span>
              .
            </li>
            <li>
              Thus{' '}
              <MathTex
                tex={String.raw`d\omega = \frac{dl}{r}\cdot\frac{dl}{r} = \frac{dA^{\perp}}{r^2} = \frac{dA\cos\theta_l}{r^2}`}
              />
              <span className="al-live" data-testid="step-6a-result">
                {' '}
                = {fmt(patch.approx, 6)} sr for this patch
              </span>
              .
            </li>
          </ol>
        </Derivation>
        <div className="al-6a">
          <div className="al-6a-figure">
            <PatchFigure patch={patch} />
            <div className="al-patch-controls">
              <Slider
                label="Patch position u on the light"
                value={pu}
                min={0}
                max={1}
                step={0.01}
                onChange={(x) => set({ pu: x })}
              />
              <Slider
                label="Patch position v on the light"
                value={pv}
                min={0}
                max={1}
                step={0.01}
                onChange={(x) => set({ pv: x })}
              />
              <Slider
                label="Patch side"
                value={psize}
                min={0.001}
                max={2}
                log
                onChange={(x) => set({ psize: x })}
              />
              <Slider
                label="Patch tilt θ_l (relative to the light)"
                value={ptilt}
                min={-89}
                max={89}
                step={1}
                unit="°"
                onChange={(x) => set({ ptilt: x })}
              />
            </div>
          </div>
          <LiveAnswer
            title="Check, computed live: the formula against the exact solid angle of the patch"
            testId="answer-6a"
          >
            <p className="al-note">
              The formula is exact only in the limit of a small patch. The exact solid angle of the orange
              patch (Van Oosterom–Strackee) and dA cos θ_l / r² agree better and better as the patch shrinks —
              the relative difference falls like the square of its size (slope 2 below).
            </p>
            <div className="al-readouts">
              <Readout
                id="patch-exact"
                label="exact Ω of the patch"
                value={patch.exact}
                digits={8}
                unit="sr"
              />
              <Readout id="patch-approx" label="dA cos θ_l / r²" value={patch.approx} digits={8} unit="sr" />
              <Readout id="patch-rel-error" label="relative difference" value={patch.relError} digits={3} />
              <Readout id="patch-r" label="r" value={patch.r} digits={5} />
              <Readout id="patch-cos" label="cos θ_l" value={patch.cosThetaL} digits={5} />
            </div>
            <Plot
              ariaLabel="Relative difference between dA cos θ_l / r² and the exact solid angle of the patch, against the patch side, log-log: a line of slope 2."
              data={patchTraces}
              height={240}
              layout={{
                xaxis: { type: 'log', title: { text: 'patch side' } },
                yaxis: { type: 'log', title: { text: 'relative difference' } },
                showlegend: false,
              }}
            />
          </LiveAnswer>
        </div>
      </ExamPart>

      <ExamPart
        id="6b"
        title="The rendering equation over the light’s area"
        asks={
          <>
            Rewrite the rendering equation, an integral over solid angle, as an integral over the area A of
            the light.
          </>
        }
      >
        <Derivation testId="derivation-6b">
          <ol className="al-steps">
            <li>
              Over directions:{' '}
              <MathTex
                display
                tex={String.raw`L_o(x,\omega_o) = \int_{\Omega} f(x,\omega_o,\omega_i)\,L_i(x,\omega_i)\cos\theta\,d\omega_i`}
              />
            </li>
            <li>
              Change of variables from ω_i to the point y on the light: dω_i = J_T dA, which introduces a
              Jacobian:
              <MathTex
                display
                tex={String.raw`L_o(x,\omega_o) = \int_{A} f\,L_i\cos\theta\,\colorbox{${hl.jBg}}{$\color{${hl.jFg}}J_T$}\,dA`}
              />
            </li>
            <li>
              Over points of the light, nothing says whether the segment from x to y is blocked (over
              directions, L_i already included it), so visibility is added explicitly:
              <MathTex
                display
                tex={String.raw`L_o(x,\omega_o) = \int_{A} f\,L_i\,\colorbox{${hl.vBg}}{$\color{${hl.vFg}}V(x,y)$}\cos\theta\,J_T\,dA`}
              />
            </li>
            <li>
              The Jacobian is Q6(a)’s dω/dA:
              <MathTex
                display
                tex={String.raw`L_o(x,\omega_o) = \int_{A} f\,L_i\,\colorbox{${hl.vBg}}{$\color{${hl.vFg}}V(x,y)$}\,\cos\theta\,\colorbox{${hl.jBg}}{$\color{${hl.jFg}}\dfrac{\cos\theta_l}{r^2}$}\,dA_y`}
              />
              <span className="al-live" data-testid="step-6b-jacobian">
                For the patch of (a): J_T = cos θ_l / r² = {fmt(patch.cosThetaL / (patch.r * patch.r))} per
                unit area.
              </span>
            </li>
          </ol>
          <p>
            The <span className="al-hl-j">Jacobian cos θ_l / r²</span> turns area into solid angle; the{' '}
            <span className="al-hl-v">visibility V</span> is 1 where y is seen from x and 0 where it is
            blocked.
          </p>
          <KeyNote testId="keynote-6b">
            the key writes L_i(x, ω_i) and V(x, ω_i) inside the area integral; over A they are functions of
            the point y on the light (ω_i is the direction from x to y), as written here.
          </KeyNote>
        </Derivation>
        <LiveAnswer testId="answer-6b">
          <div className="al-readouts">
            <Readout
              id="reference"
              label="reference (Lambert, no occluder)"
              value={model.reference}
              digits={7}
            />
            <Readout
              id="reference-occluded"
              label="reference with occluder (V < 1)"
              value={model.occluder ? model.referenceOccluded : null}
              digits={7}
            />
            <Readout
              id="projected-solid-angle"
              label="∫ cos θ dω (clipped to the horizon)"
              value={model.projectedSolidAngle}
              digits={7}
              unit="sr"
            />
            <Readout
              id="solid-angle"
              label="solid angle Ω of the light"
              value={model.solidAngle}
              digits={7}
              unit="sr"
            />
            <Readout
              id="solid-angle-closed"
              label="Ω, closed form (light parallel to floor)"
              value={model.solidAngleClosed}
              digits={7}
              unit="sr"
            />
          </div>
          <p className="al-note">
            For a Lambertian floor f = ρ/π, and the integral has a closed form: L_o = (ρ/π) L ∫ cos θ dω by
            Lambert’s formula.
          </p>
        </LiveAnswer>
      </ExamPart>

      <ExamPart
        id="6c"
        title="Monte Carlo estimator with uniform area sampling"
        asks={
          <>
            Sampling points uniformly on the light’s area, give the pdf and the Monte Carlo estimator of L_o.
          </>
        }
      >
        <Derivation testId="derivation-6c">
          <ol className="al-steps">
            <li>
              The pdf is uniform over the light’s area: <MathTex tex={String.raw`p_A = \frac{1}{|A|}`} />
              <span className="al-live" data-testid="step-6c-pdf">
                {' '}
                (|A| = {fmt(given.area)}, p_A = {fmt(1 / given.area)})
              </span>
              .
            </li>
            <li>
              The MC estimator divides each term of the area integral by p_A:
              <MathTex
                display
                tex={String.raw`\langle L_o\rangle = \frac{1}{N}\sum_{i=1}^{N}\frac{f\,L_i\,V\cos\theta_i\,\cos\theta_{l,i}/r_i^2}{p_A} = \frac{|A|}{N}\sum_{i=1}^{N} f\,L_i\,V_i\cos\theta_i\,\frac{\cos\theta_{l,i}}{r_i^2}`}
              />
            </li>
            <li>
              With numbers — the first four samples of seed {seed} (f = ρ/π = {fmt(fArea)}, L = {fmt(model.L)}
              ):
              <div
                className="al-table-wrap"
                tabIndex={0}
                role="group"
                aria-label="The first four samples (the table scrolls sideways on narrow screens)"
              >
                <table className="al-table al-given" data-testid="given-samples">
                  <thead>
                    <tr>
                      <th scope="col">i</th>
                      <th scope="col">(ξ₁, ξ₂)</th>
                      <th scope="col">y_i on the light</th>
                      <th scope="col">r_i</th>
                      <th scope="col">cos θ_i</th>
                      <th scope="col">cos θ_l,i</th>
                      <th scope="col">V_i</th>
                      <th scope="col">|A| f L V cos θ cos θ_l / r²</th>
                    </tr>
                  </thead>
                  <tbody>
                    {given.samples.map((g, i) => (
                      <tr key={i} data-testid={`given-${i + 1}`}>
                        <th scope="row">{i + 1}</th>
                        <td>
                          {fmt(g.u1, 3)}, {fmt(g.u2, 3)}
                        </td>
                        <td>
                          ({fmt(g.x[0], 3)}, {fmt(g.x[1], 3)}, {fmt(g.x[2], 3)})
                        </td>
                        <td>{fmt(g.r)}</td>
                        <td>{fmt(g.cosTheta)}</td>
                        <td>{fmt(g.cosThetaL)}</td>
                        <td>{g.V}</td>
                        <td data-testid={`given-term-${i + 1}`} data-value={String(g.term)}>
                          {fmt(g.term, 5)}
                        </td>
                      </tr>
                    ))}
                  </tbody>
                </table>
              </div>
              <MathTex
                display
                tex={String.raw`\langle L_o\rangle_{N=4} = \tfrac{1}{4}\big(${given.samples.map((g) => fmt(g.term, 5)).join(' + ')}\big) = ${fmt(given.estimate, 5)}`}
              />
              <Readout
                id="given-estimate"
                label="⟨L_o⟩ from these 4 samples"
                value={given.estimate}
                digits={7}
              />
            </li>
          </ol>
        </Derivation>
        {answer6c}
      </ExamPart>
    </>
  );
});
