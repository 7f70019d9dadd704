/**
 * Solid angle and area lights (exam Q6): dω = dA cos θₗ / r² drawn, the rendering equation over
 * solid angle and over area, and three estimators of the light reflected by a Lambertian floor —
 * uniform area (the key's), solid-angle (spherical rectangle) and cosine hemisphere sampling —
 * against the analytic reference (Lambert's formula). All figures come from ./model over the core;
 * this file holds the scene's state and layout, the exam parts are in exam/, the figures in view/.
 */
import { lazy, useCallback, useEffect, useMemo, useRef, useState } from 'react';
import type { SceneProps } from '../../kit/scene';
import { ExamQuestion, ExploreFurther, Notice, Revealed, SceneLayout, useTimeline } from '../../ui';
import { prefersReducedMotion } from '../../ui/timeline';
import { useWorkerJob } from '../../workers';
import { Fold } from '../../ui/Fold';
import { makeWorker } from './jobs';
import { animationLength } from './animation';
import { buildModel, SYNC_MAX, targetValue, type StrategyEstimate } from './model';
import { patchModel } from './patch';
import { floorJob, floorPassAt } from './floor';
import { schema, type AreaLightParams } from './params';
import { Q6a } from './exam/Q6a';
import { Q6b } from './exam/Q6b';
import { Answer6c, Q6c } from './exam/Q6c';
import { Controls } from './view/Controls';
import { ExamConfig } from './view/ExamConfig';
import { Legend, Stage } from './view/Stage';
import './area-light.css';

// What the folds hold is loaded when a fold is first opened (each fold's Suspense says "Loading…"),
// not with the page: the first screen is the exam and the stage.
const RunningData = lazy(() => import('./view/RunningData').then((m) => ({ default: m.RunningData })));
const StrategyTable = lazy(() => import('./view/StrategyTable').then((m) => ({ default: m.StrategyTable })));
const ConvergencePanel = lazy(() => import('./view/Explore').then((m) => ({ default: m.ConvergencePanel })));
const TimingPanel = lazy(() => import('./view/Explore').then((m) => ({ default: m.TimingPanel })));
const FloorPanel = lazy(() => import('./view/FloorImages').then((m) => ({ default: m.FloorPanel })));

type Schema = typeof schema;

export default function AreaLightScene({ params, setParams, mode }: SceneProps<Schema>) {
  const set = useCallback((patch: Partial<AreaLightParams>) => setParams(patch), [setParams]);
  const model = useMemo(() => buildModel(params), [params]);
  const { strategy, n, seed } = params;

  // Up to SYNC_MAX samples per strategy Q6(c)'s estimate is computed on the main thread, in that
  // answer's own render (it mounts with its exam part, not in the page's first render); beyond, in
  // a worker, so a slider drag never blocks the page, and the worker's three estimates also fill
  // the strategies' table. Below SYNC_MAX the table computes its own, once its fold is opened.
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
  const estKey = `${timingKey}|${n}`;
  const estTask = useWorkerJob(makeWorker, 'estimates', params, {
    enabled: big,
    delayMs: 150,
  });
  /** The worker's three estimates (n > SYNC_MAX), null until they arrive or when n is small. */
  const workerEstimates: StrategyEstimate[] | null = big ? (estTask.result ?? null) : null;
  const pending = big && !estTask.result;
  const target = targetValue(model);
  const { pu, pv, psize, ptilt } = params;
  const patchValues = useMemo(() => ({ pu, pv, psize, ptilt }), [pu, pv, psize, ptilt]);
  const patch = useMemo(() => patchModel(model, pu, pv, psize, ptilt), [model, pu, pv, psize, ptilt]);
  // Convergence series (3 × 32768 samples) in the worker: ~0.1 s that a slider drag should not wait for.
  // The convergence and timing runs start when their panels are opened and seen (not on load:
  // their results re-render the scene while the first screen should be answering input). Each
  // panel watches its own box and reports once it has been seen: the panels mount only when their
  // folds open, so a box watched from here would still be empty when the watching starts, and the
  // runs would never start.
  const [convSeen, setConvSeen] = useState(false);
  const [timingSeen, setTimingSeen] = useState(false);
  const onConvSeen = useCallback(() => setConvSeen(true), []);
  const onTimingSeen = useCallback(() => setTimingSeen(true), []);
  const convArgs = useMemo(() => ({ params, nMax: 1 << 15 }), [params]);
  const convTask = useWorkerJob(makeWorker, 'convergence', convArgs, {
    key: timingKey,
    delayMs: 120,
    enabled: convSeen,
  });
  const timing = useWorkerJob(makeWorker, 'timing', params, {
    key: timingKey,
    delayMs: 400,
    enabled: timingSeen,
  });

  const job = useMemo(() => floorJob(model, seed), [model, seed]);

  // The animation: t = samples of the chosen strategy arrived so far, 0 … min(n, 1024).
  // Asked to predict first (ask=1), it is held at its start; on Reveal it plays from there.
  const animMax = animationLength(n);
  const stageRef = useRef<HTMLDivElement>(null);
  const [held, setHeld] = useState(mode.ask);
  useEffect(() => {
    if (mode.ask || !held) return;
    setHeld(false);
    setParams({ t: 0, play: !prefersReducedMotion() });
  }, [mode.ask, held, setParams]);
  const tl = useTimeline({
    t: held ? 0 : params.t,
    play: held ? false : params.play,
    setParams,
    max: animMax,
    integer: true,
    duration: Math.max(4, animMax / 64),
    visibleRef: stageRef,
    // while playing, the scene (readouts, floor pass) re-renders 4 times a second; the 3D samples
    // and the running-estimate plot follow every frame by direct writes (view/Stage)
    renderHz: 4,
  });
  const floorPass = floorPassAt(tl.t, animMax);

  // "Reseed every second": a new seed each second, to watch the estimate jitter within its error bar.
  const [reseeding, setReseeding] = useState(false);
  const toggleReseeding = useCallback(() => setReseeding((p) => !p), []);
  useEffect(() => {
    if (!reseeding) return;
    const t = setInterval(() => setParams({ seed: (Date.now() >>> 0) % 4294967295 }), 1000);
    return () => clearInterval(t);
  }, [reseeding, setParams]);

  const dark = mode.theme === 'dark';
  const ask = mode.ask;

  // The chosen strategy's run, which its answer, the stage and the running data all show.
  const chosen = useMemo(
    () => ({ model, strategy, seed, reference: target }),
    [model, strategy, seed, target],
  );
  // The panels and exam parts are memoised on their props (not on t), so an animation frame
  // re-renders only the stage's animated bits and the floor images' pass choice; each exam part
  // renders on its own, so React can yield between the scene's render and theirs.
  const answer6c = useMemo(
    () => <Answer6c {...chosen} n={n} big={big} estimates={workerEstimates} pending={pending} />,
    [chosen, n, big, workerEstimates, pending],
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
        intro={
          <p>
            A rectangular area light of radiance L shines on a floor point x (normal +z, Lambertian, albedo
            ρ). (a) Derive dω = dA cos θ<sub>l</sub> / r² by similar triangles; (b) write the rendering
            equation over the light’s area; (c) give the Monte Carlo estimator with uniform area sampling.
          </p>
        }
      >
        <Legend strategy={strategy} />
        <Fold name="running-data" summary="The running estimate as sound and as a table">
          <Revealed ask={ask} what="the running estimate as sound and as a table">
            <RunningData {...chosen} count={animMax} t={tl.t} />
          </Revealed>
        </Fold>
        <Q6a patch={patch} values={patchValues} set={set} ask={ask} />
        <Q6b patch={patch} model={model} dark={dark} ask={ask} />
        <Q6c model={model} seed={seed} answer={answer6c} ask={ask} />
      </ExamQuestion>
      <ExploreFurther intro="Beyond the exam: two other ways to sample the same integral, how fast each converges, what it costs, and what its noise looks like on a whole floor. Each opens on a click.">
        {/* one child: the four folds mount together (closed, they are four lines) */}
        <>
          <Fold name="strategies" summary="The three strategies’ estimates side by side">
            <Revealed ask={ask} what="the three strategies’ estimates">
              <StrategyTable
                model={model}
                strategy={strategy}
                n={n}
                seed={seed}
                target={target}
                estKey={estKey}
                fromWorker={workerEstimates}
              />
            </Revealed>
          </Fold>
          <Fold name="convergence" summary="Convergence: each strategy’s error against N">
            <Revealed ask={ask} what="the convergence of the three strategies">
              <ConvergencePanel conv={convTask.result} onSeen={onConvSeen} present={mode.present} />
            </Revealed>
          </Fold>
          <Fold name="timing" summary="Run time against error, on this machine">
            <Revealed ask={ask} what="the run time against error">
              <TimingPanel
                result={timing.result}
                running={timing.running}
                progress={timing.progress}
                error={timing.error}
                onSeen={onTimingSeen}
                present={mode.present}
              />
            </Revealed>
          </Fold>
          <Fold name="floor" summary="The whole floor rendered with each strategy">
            <Revealed ask={ask} what="the floor images">
              <FloorPanel job={job} pass={floorPass} />
            </Revealed>
          </Fold>
        </>
      </ExploreFurther>
    </>
  );

  const controls = (
    <Controls params={params} set={set} reseeding={reseeding} onToggleReseeding={toggleReseeding} />
  );
  const stage = (
    <>
      <ExamConfig params={params} tilt={model.tilt} patchCos={patch.cosThetaL} set={set} />
      <Stage {...chosen} tl={tl} stageRef={stageRef} count={animMax} patch={patch} mode={mode} />
    </>
  );
  return <SceneLayout controls={controls} main={main} stage={stage} />;
}
