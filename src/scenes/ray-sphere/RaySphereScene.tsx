/**
 * #/ray-sphere — exam Q5, exam first: the question, the figure with its sweep animation (the ray
 * moves across the sphere on the shared timeline) beside g(t), the written derivation with live
 * numbers, the live answer; everything else (typed values and settings, Δ along the sweep, the
 * t_min note, and beyond the exam the 3D view and what floating point does to the textbook form,
 * Ray Tracing Gems ch. 7) is folded, one click away. This file holds the state and the layout; the
 * exam's blocks are in exam/, the figures in view/.
 */
import { useCallback, useDeferredValue, useEffect, useMemo, useRef } from 'react';
import type { SceneProps } from '../../kit/scene';
import {
  Deferred,
  ExamPart,
  ExamQuestion,
  lastValue,
  Revealed,
  SceneLayout,
  useHeldWhile,
  useThrottled,
  useTimeline,
} from '../../ui';
import type { RaySphereParams, schema } from './params';
import { checkInputs } from './inputs';
import { computeModel } from './model';
import { makeSweep, paramsAt, sweepAt } from './sweep';
import { Q5Answer } from './exam/Q5Answer';
import { Q5Asks } from './exam/Q5Asks';
import { Q5Controls } from './exam/Q5Controls';
import { activePresetOf, CasePresets } from './exam/Q5Presets';
import { Q5Derivation } from './exam/Q5Derivation';
import { Q5Figure } from './exam/Q5Figure';
import { Q5Plots } from './exam/Q5Plots';
import { InputNotices } from './view/InputNotices';
import { RaySphereExplore } from './view/Explore';
import './ray-sphere.css';

/**
 * Placeholder heights (px) of the first screen's blocks until they mount: the cross-section with
 * the case banner, the transport and the case presets; the g(t) plot with the Δ plot's fold; the
 * method and the folded settings.
 */
const STAGE_FIG_ESTIMATE = 720;
const PLOTS_ESTIMATE = 380;
const CONTROLS_ESTIMATE = 160;

/** Seconds for one sweep (τ from 0 to 1) at 1× speed. */
const SWEEP_SECONDS = 10;

export default function RaySphereScene({ params, setParams, mode }: SceneProps<typeof schema>) {
  const { method, sweep: sweepMode, extent } = params;
  // the sweep is centred on the configuration typed in o, d (t = 0.5); it depends on params, not on t
  const base = useMemo(() => checkInputs(params), [params]);
  const sweep = useMemo(() => makeSweep(base, sweepMode, extent), [base, sweepMode, extent]);

  const stageRef = useRef<HTMLDivElement>(null);
  // While playing, this component (readouts, case banner, notes) re-renders only RENDER_HZ times a
  // second; the figures that move every frame (the cross-section and the two plots) follow the
  // timeline's frames in their own small components (view/Live.tsx).
  const tl = useTimeline({
    t: params.t,
    // ask=1: held where the link opens (the typed ray) until revealed; the sweep is hidden then
    play: params.play && !mode.ask,
    shortcuts: !mode.ask,
    setParams,
    max: 1,
    duration: SWEEP_SECONDS,
    stepSize: 1 / 120,
    loop: true,
    visibleRef: stageRef,
    renderHz: 0,
  });
  const modelAt = useMemo(
    () => lastValue((tt: number) => computeModel(paramsAt(params, sweep, tt))),
    [params, sweep],
  );
  const model = modelAt(tl.t);

  // Edits (drags, typing) describe the ray you see (at the live position): they become the
  // sweep's centre (t = 0.5).
  const liveRef = useRef({ sweep, now: tl.now });
  liveRef.current = { sweep, now: tl.now };
  const edit = useCallback(
    (patch: Partial<RaySphereParams>) => {
      const tNow = liveRef.current.now();
      const cur = sweepAt(liveRef.current.sweep, tNow);
      if (tNow === 0.5) setParams(patch);
      else setParams({ o: [...cur.o], d: [...cur.d], ...patch, t: 0.5, play: false });
    },
    [setParams],
  );
  // Drags fire pointer events faster than frames: coalesce parameter updates to one per frame.
  const pending = useRef<Partial<RaySphereParams> | null>(null);
  const raf = useRef(0);
  const editSoon = useCallback(
    (patch: Partial<RaySphereParams>) => {
      pending.current = { ...pending.current, ...patch };
      if (raf.current) return;
      raf.current = requestAnimationFrame(() => {
        raf.current = 0;
        const p = pending.current;
        pending.current = null;
        if (p) edit(p);
      });
    },
    [edit],
  );
  useEffect(() => {
    // a link followed (a new address) replaces the state: an edit still waiting for its frame
    // would otherwise land on top of the link's values
    const drop = () => {
      cancelAnimationFrame(raf.current);
      raf.current = 0;
      pending.current = null;
    };
    window.addEventListener('hashchange', drop);
    return () => {
      window.removeEventListener('hashchange', drop);
      cancelAnimationFrame(raf.current);
    };
  }, []);

  // Heavy panels (KaTeX, the precision table) follow a throttled, deferred copy: the figure, the
  // plots and the readouts update every frame; the derivation at most every 200 ms (and always
  // with the final values). While the sweep plays they hold the numbers of the position where it
  // started (a KaTeX re-render mid-animation costs more than a frame); they catch up when it pauses.
  const held = useHeldWhile(model, tl.playing);
  const slow = useDeferredValue(useThrottled(held, 200));

  const activePreset = activePresetOf(params);
  const ends = useMemo(() => [sweepAt(sweep, 0).o, sweepAt(sweep, 1).o], [sweep]);
  const live = { tl, modelAt };

  const ask = mode.ask;
  // In classroom mode the figure, the case and the transport are the stage (first, filling the
  // first screen) and the sweep's settings, the presets and typed values are the drawer; the exam
  // follows below.
  const staged = mode.present;
  const figure = (staged: boolean) => (
    <Q5Figure
      {...live}
      sweep={sweep}
      ends={ends}
      onDrag={editSoon}
      method={method}
      ask={ask}
      staged={staged}
      boxRef={staged ? stageRef : undefined}
    />
  );
  const { o, d, c, r, precision } = params;
  const controls = (
    <Q5Controls
      {...{ o, d, c, r, method, precision, sweep, extent, edit, setParams }}
      active={activePreset}
      staged={staged}
    />
  );
  const plots = (
    <Deferred estimate={PLOTS_ESTIMATE}>
      <Revealed ask={ask} what="g(t) and Δ along the sweep, with their roots and cases" minHeight={200}>
        <Q5Plots {...live} sweep={sweep} method={method} />
      </Revealed>
    </Deferred>
  );
  const exam = (
    <ExamQuestion n={5}>
      <ExamPart id="5" title="The quadratic, Δ ≥ 0 and t ≥ 0" asks={<Q5Asks />}>
        {/* Each block of the part mounts on its own (ui/Deferred: one at a time, a frame each, the
            figure first), so opening the page is several short commits and layouts instead of
            one long one. The placeholders hold the blocks' places in the stage grid. */}
        {staged ? (
          <div className="rs-stage-plots rs-staged-plots">{plots}</div>
        ) : (
          <div className="rs-stage" ref={stageRef}>
            <div className="rs-stage-fig">
              <Deferred estimate={STAGE_FIG_ESTIMATE}>
                {figure(false)}
                <CasePresets active={activePreset} setParams={setParams} />
              </Deferred>
            </div>
            <div className="rs-stage-plots">{plots}</div>
            <div className="rs-stage-ctl">
              <Deferred estimate={CONTROLS_ESTIMATE}>{controls}</Deferred>
            </div>
          </div>
        )}
        <Deferred estimate={600}>
          <Revealed ask={ask} what="the derivation with these numbers" minHeight={160}>
            <Q5Derivation model={slow} playing={tl.playing} />
          </Revealed>
        </Deferred>
        <Deferred estimate={480}>
          <Revealed ask={ask} what="the live answer: Δ, the roots, the hit and the case" minHeight={120}>
            <Q5Answer {...live} sweep={sweep} method={method} />
          </Revealed>
        </Deferred>
      </ExamPart>
    </ExamQuestion>
  );
  const explore = (
    <RaySphereExplore
      {...live}
      slow={slow}
      ends={ends}
      present={mode.present}
      dark={mode.theme === 'dark'}
      ask={ask}
    />
  );

  return (
    <div className="rs-page">
      {/* problems are those of the typed inputs (the sweep only moves already-checked values) */}
      <InputNotices problems={base.failures} fatal={model.fatal} />
      {staged ? (
        <SceneLayout
          stage={figure(true)}
          controls={controls}
          main={
            <>
              {exam}
              {explore}
            </>
          }
        />
      ) : (
        <>
          {exam}
          {explore}
        </>
      )}
    </div>
  );
}
