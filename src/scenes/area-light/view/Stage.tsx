/**
 * The animated stage of #/area-light: the 3D view with the samples of the chosen strategy that have
 * arrived at the timeline's position, the transport, the running estimate and its readouts. The 3D
 * samples and the running-estimate plot follow every frame by direct writes (no React render).
 */
import { useCallback, useMemo, useRef, type ComponentProps, type RefObject } from 'react';
import {
  DescribedFigure,
  Readout,
  Revealed,
  TEXT_HZ,
  TimelineTransport,
  useTimelineFrame,
  type Timeline,
} from '../../../ui';
import type { LightStrategy } from '../../../core/lights';
import type { SceneMode } from '../../../kit/scene';
import { animationFrame, sampleRun, type SampleRun } from '../animation';
import { STRATEGY_LABEL, STRATEGY_SHORT } from '../strategies';
import { type AreaLightModel } from '../model';
import { describeAreaLight, describeRunning } from './describe';
import { RunningEstimate } from './RunningEstimate';
import { Scene3D } from './Scene3D';

/** The 3D view with the samples arrived at the timeline's live position (drawn per frame, no React render). */
function LiveScene3D({
  tl,
  run,
  ...rest
}: { tl: Timeline; run: SampleRun } & Omit<
  ComponentProps<typeof Scene3D>,
  'strategy' | 'samples' | 'terms' | 'count' | 'countRef'
>) {
  const countRef = useRef<((k: number) => void) | null>(null);
  const latest = useRef(run);
  latest.current = run;
  useTimelineFrame(tl, (t) => countRef.current?.(animationFrame(latest.current, t).k));
  return (
    <Scene3D
      {...rest}
      strategy={run.strategy}
      samples={run.points}
      terms={run.terms}
      count={animationFrame(run, tl.now()).k}
      countRef={countRef}
    />
  );
}

/**
 * The running-estimate plot at the timeline's live position (drawn per frame without a React
 * render; its text label at most TEXT_HZ times a second).
 */
function LiveRunning({ tl, run, reference }: { tl: Timeline; run: SampleRun; reference: number }) {
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
  const k = animationFrame(run, tl.t).k;
  return (
    <DescribedFigure
      label="Running estimate against samples k"
      description={describeRunning(run, k, reference)}
      playing={tl.playing}
      quiet
      testId="al-running-figure"
    >
      <RunningEstimate
        run={run}
        reference={reference}
        k={animationFrame(run, tl.now()).k}
        drawRef={drawRef}
      />
    </DescribedFigure>
  );
}

/**
 * The animated stage: the 3D view with the samples arrived so far, the transport, the running
 * estimate and its readouts. Its own component, so that its sample run is computed in a render of
 * its own: React can yield between the scene's render and this one, which keeps a phone's first
 * render from being one long task.
 */
export function Stage({
  tl,
  stageRef,
  model,
  strategy,
  count,
  seed,
  reference: target,
  patch,
  mode,
}: {
  tl: Timeline;
  stageRef: RefObject<HTMLDivElement | null>;
  model: AreaLightModel;
  strategy: LightStrategy;
  /** Samples in the animation. */
  count: number;
  seed: number;
  reference: number;
  patch: NonNullable<ComponentProps<typeof Scene3D>['patch']>;
  /** Asked to predict first (`mode.ask`): the running estimate and the transport are hidden. */
  mode: SceneMode;
}) {
  const { ask } = mode;
  // what the 3D view shows besides the samples; in classroom mode it fills the stage's height (CSS),
  // elsewhere it has a fixed height
  const view = { model, patch, height: mode.present ? '100%' : 380, dark: mode.theme === 'dark' };
  const run = useMemo(() => sampleRun(model, strategy, count, seed), [model, strategy, count, seed]);
  const af = animationFrame(run, tl.t);
  const fmtPos = useCallback((t: number) => `${Math.floor(t)} of ${count} samples`, [count]);
  const description = describeAreaLight(model, patch, { strategy, run, frame: af, target, hidden: ask });
  return (
    <div className="al-stage-wrap">
      <DescribedFigure
        label="The area light, the shading point and the samples arriving"
        description={description}
        playing={tl.playing}
        testId="al-figure"
        className="stage-figure"
      >
        <div className="al-stage" ref={stageRef}>
          <div className="al-stage-3d">
            <LiveScene3D tl={tl} run={run} {...view} />
          </div>
          <div className="al-stage-transport">
            <Revealed
              ask={ask}
              what="the samples arriving (Reveal, then they play)"
              testId="ask-hidden-transport"
            >
              <TimelineTransport
                timeline={tl}
                label={`Samples arriving (${STRATEGY_SHORT[strategy]})`}
                format={fmtPos}
              />
            </Revealed>
          </div>
          <div className="al-stage-side">
            <div className="al-readouts al-anim-readouts">
              <Readout id="anim-k" label="samples arrived k" value={af.k} digits={7} />
              <Revealed ask={ask} what="the running estimate">
                <Readout
                  id="anim-estimate"
                  label="running estimate"
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
              </Revealed>
            </div>
            <Revealed ask={ask} what="the running-estimate plot" testId="ask-hidden-running">
              <LiveRunning tl={tl} run={run} reference={target} />
            </Revealed>
          </div>
        </div>
      </DescribedFigure>
    </div>
  );
}

/** What the colours and shapes of the 3D view mean (shown under the question, outside the stage). */
export function Legend({ strategy }: { strategy: LightStrategy }) {
  return (
    <p className="al-legend">
      Yellow: the emitting side of the light (its back is dark). Dots: the samples of the{' '}
      {STRATEGY_LABEL[strategy]} strategy arrived so far
      {strategy === 'cosine'
        ? ', as directions on the unit hemisphere'
        : ' on the light, and their directions on the unit hemisphere'}{' '}
      — large green dots where the sample contributes, small red dots where it is wasted (below the horizon,
      blocked, or missing the light); lines to the newest. Orange: the Q6(a) patch and its projection on the
      unit sphere. The small plot (beside the view, or below it on narrow screens): the running estimate with
      ±2 standard errors, converging on the reference (dashed).
    </p>
  );
}
