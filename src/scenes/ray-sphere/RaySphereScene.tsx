/**
 * #/ray-sphere — exam Q5, exam first: the question, the figure with its sweep animation (the ray
 * moves across the sphere on the shared timeline), the written derivation with live numbers, the
 * live answer, and then, beyond the exam, the 3D view and what floating point does to the
 * textbook form (Ray Tracing Gems ch. 7). This file holds the state and the layout; the exam's
 * blocks are in exam/, the figures in view/.
 */
import { memo, useCallback, useDeferredValue, useEffect, useMemo, useRef } from 'react';
import type { SceneProps } from '../../kit/scene';
import {
  Deferred,
  ExamPart,
  ExamQuestion,
  ExploreFurther,
  lastValue,
  Panel,
  useHeldWhile,
  useThrottled,
  useTimeline,
} from '../../ui';
import type { RaySphereParams, schema } from './params';
import { checkInputs, computeModel, makeSweep, paramsAt, sweepAt } from './model';
import { Q5Answer } from './exam/Q5Answer';
import { Q5Asks } from './exam/Q5Asks';
import { activePresetOf, Q5Fields, Q5Presets } from './exam/Q5Controls';
import { Q5Derivation } from './exam/Q5Derivation';
import { Q5Figure } from './exam/Q5Figure';
import { Q5Plots } from './exam/Q5Plots';
import { InputNotices } from './view/InputNotices';
import { LiveView3D } from './view/Live';
import { LiveDescribed } from './view/Described';
import { describe3D } from './view/describe';
import { DistantImages, ErrorVsDistance, PrecisionTable } from './view/Precision';
import { PrecisionExplainer } from './view/PrecisionExplainer';
import { PrecisionCompare } from './view/Float32Panel';
import { GpuSection } from './view/gpu';
import './ray-sphere.css';

/** The figure block's placeholder height (px): the cross-section, the case banner and the transport. */
const STAGE_FIG_ESTIMATE = 720;

/** Seconds for one sweep (t from 0 to 1) at 1× speed. */
const SWEEP_SECONDS = 10;

const DistantImagesMemo = memo(DistantImages);
const ErrorVsDistanceMemo = memo(ErrorVsDistance);
const PrecisionTableMemo = memo(PrecisionTable);
const PrecisionCompareMemo = memo(PrecisionCompare);

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
    play: params.play,
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
      else setParams({ o: cur.o, d: cur.d, ...patch, t: 0.5, play: false });
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
  useEffect(() => () => cancelAnimationFrame(raf.current), []);

  // Heavy panels (KaTeX, the precision table) follow a throttled, deferred copy: the figure, the
  // plots and the readouts update every frame; the derivation at most every 200 ms (and always
  // with the final values). While the sweep plays they hold the numbers of the position where it
  // started (a KaTeX re-render mid-animation costs more than a frame); they catch up when it pauses.
  const held = useHeldWhile(model, tl.playing);
  const slow = useDeferredValue(useThrottled(held, 200));

  const hereErrors = useMemo(
    () => ({
      naive: slow.rows.find((x) => x.method === 'naive')?.errDisc ?? null,
      stable: slow.rows.find((x) => x.method === 'stable')?.errDisc ?? null,
    }),
    [slow],
  );
  const activePreset = activePresetOf(params);
  const ends = useMemo(() => [sweepAt(sweep, 0).o, sweepAt(sweep, 1).o], [sweep]);
  const live = { tl, modelAt };

  return (
    <div className="rs-page">
      {/* problems are those of the typed inputs (the sweep only moves already-checked values) */}
      <InputNotices problems={base.failures} fatal={model.fatal} />
      <ExamQuestion n={5}>
        <ExamPart id="5" title="The quadratic, Δ ≥ 0 and t ≥ 0" asks={<Q5Asks />}>
          {/* Each block of the part mounts on its own (ui/Deferred: one at a time, a frame each, the
              figure first), so opening the page is several short commits and layouts instead of
              one long one. The placeholders hold the blocks' places in the stage grid. */}
          <div className="rs-stage" ref={stageRef}>
            <div className="rs-stage-fig">
              <Deferred estimate={STAGE_FIG_ESTIMATE}>
                <Q5Figure
                  {...live}
                  sweep={sweep}
                  extent={extent}
                  ends={ends}
                  onDrag={editSoon}
                  setParams={setParams}
                  method={method}
                />
              </Deferred>
            </div>
            <div className="rs-stage-ctl">
              <Deferred estimate={360}>
                <Q5Presets active={activePreset} setParams={setParams} />
                <Q5Fields
                  o={params.o}
                  d={params.d}
                  c={params.c}
                  r={params.r}
                  method={method}
                  precision={params.precision}
                  setParams={setParams}
                  edit={edit}
                />
              </Deferred>
            </div>
            <div className="rs-stage-plots">
              <Deferred estimate={640}>
                <Q5Plots {...live} sweep={sweep} method={method} />
              </Deferred>
            </div>
          </div>
          <Deferred estimate={600}>
            <Q5Derivation model={slow} playing={tl.playing} />
          </Deferred>
          <Deferred estimate={480}>
            <Q5Answer {...live} sweep={sweep} method={method} />
          </Deferred>
        </ExamPart>
      </ExamQuestion>
      <ExploreFurther intro="Beyond the exam: the same ray in 3D, and what floating point does to the textbook formula when the sphere is far away or the ray grazes it.">
        <Panel title="3D view">
          <LiveDescribed
            {...live}
            label="3D view of the ray and the sphere"
            describe={describe3D}
            quiet
            testId="view3d-figure"
          >
            <LiveView3D
              {...live}
              height={mode.present ? 420 : 320}
              dark={mode.theme === 'dark'}
              fitExtra={ends}
            />
          </LiveDescribed>
        </Panel>
        <Panel
          title="Precision: textbook vs robust, against a double-double reference"
          className="rs-offscreen-skip"
        >
          <PrecisionTableMemo model={slow} />
          <PrecisionCompareMemo model={slow} />
          <PrecisionExplainer />
        </Panel>
        <div className="rs-explore-grid">
          <Panel title="A distant sphere, one ray per pixel" className="rs-offscreen-skip">
            <DistantImagesMemo />
          </Panel>
          <Panel title="Error against distance">
            <ErrorVsDistanceMemo current={Number(slow.distanceRatio.toPrecision(3))} here={hereErrors} />
            <p className="rs-small">
              Median over 12 rays per distance, aimed 0.1 r … 0.95 r off the centre; the crosses are the
              current ray’s Δ errors. The textbook Δ loses digits like u·(D/r)² (u = 2⁻⁵³): by D ≈ 10⁸ r
              nothing is left. The robust Δ grows only like u·(D/r), and its roots stay accurate to the last
              bits. In float32 (orange and green squares; u₃₂ = 2⁻²⁴) the same happens 10⁴ times sooner: the
              textbook Δ is noise by D ≈ 1/√u₃₂ ≈ 4·10³ r, a distance every game scene has.
            </p>
          </Panel>
        </div>
        <Panel title="What the GPU sees: the sphere in float32, on a shader">
          <GpuSection />
        </Panel>
      </ExploreFurther>
    </div>
  );
}
