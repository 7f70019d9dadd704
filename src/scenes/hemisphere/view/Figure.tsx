/**
 * The figure of Q1 on the shared timeline: the warp morph of the unit square onto the hemisphere
 * (or the samples appearing one by one), its transport and toggles, the readouts and caption at the
 * current position, and the unit square beside it with the scene's settings.
 */
import { memo, useEffect, useMemo, useRef, useState, type ComponentProps, type ReactNode } from 'react';
import type { SceneProps } from '../../../kit/scene';
import {
  DescribedFigure,
  prefersReducedMotion,
  TimelineTransport,
  Toggle,
  useTimeline,
  useTimelineFrame,
  type Timeline,
} from '../../../ui';
import { formatCount } from '../../../ui/format';
import { fillSequence2D } from '../../../core/random';
import { animDuration, animFrame, type AnimFrame, type AnimKind } from '../animation';
import type { Lobe } from '../lobe';
import { Stage } from '../../../ui/stage';
import { FigureCaption, FigureReadouts } from './FigureText';
import { bindControls } from '../../../ui/paramControls';
import { schema, type HemisphereSchema } from '../params';
import { pointsArgsOf } from '../jobs';
// Static, not lazy: the 3D panel is on the first screen, and a Suspense fallback of another height
// shifted the layout when it arrived (three.js itself still loads lazily, inside Viewport).
import { HemisphereView } from './HemisphereView';
import { UnitSquare } from './UnitSquare';
import { cellImage, cellOf, type Cell } from '../stratum';
import { StratumControls, useCellCount, type PickCell } from './StratumPicker';
import { describeHemisphere, describeStratum, type HemisphereState } from './describe';

const ANIM_OPTIONS: { value: AnimKind; label: string }[] = [
  { value: 'warp', label: 'warp morph: square → hemisphere' },
  { value: 'grow', label: 'samples appear, 1 → N' },
];

const SquareMemo = memo(UnitSquare);

/**
 * The 3D view's height on the classroom stage: what the first screen leaves below the stage's top
 * (`--stage-top`, set by the stage) after the transport and the key readouts (and, while the
 * results are hidden, the line that says the warp is held).
 */
const stageViewHeight = (held: boolean) =>
  `max(9rem, calc(100dvh - var(--stage-top, 0px) - ${held ? 12 : 10.5}rem))`;

interface FigureProps extends SceneProps<HemisphereSchema> {
  /** The density sampled (null: none, and `problem` is shown instead of the 3D view). */
  lobe: Lobe | null;
  problem: ReactNode;
  /** The settings, given the figure's own options to fold with them (null: they are elsewhere). */
  settings: (more: ReactNode) => ReactNode;
  /** The followed stratum and how to choose another (stable). */
  cell: Cell | null;
  onPickCell: PickCell;
  /** The χ² test of the current draw (null while it runs), and why nothing is sampled (no lobe). */
  chi2: HemisphereState['chi2'];
  noLobeText: string;
}

/**
 * The figure on the shared timeline. While playing nothing here re-renders per frame: the 3D view
 * is driven directly from the timeline's frames (LiveHemisphereView), the readouts and caption
 * follow a coarse position (FigureText, 4 times a second), the transport writes its own position;
 * the unit square and the settings are memoised. Paused, everything renders the exact position.
 */
export function Figure({
  params,
  setParams,
  mode: { present, ask, theme },
  lobe,
  problem,
  settings,
  cell,
  onPickCell,
  chi2,
  noLobeText,
}: FigureProps) {
  const { points: kind, seed, n, anim, lobe: lobeId } = params;
  // the (ξ₁, ξ₂) points that both the unit square and the 3D view draw, and the theme they draw for
  const pointSet = { kind, seed, n, dark: theme === 'dark' };
  const play = params.play === true;
  // a link with play=1 and t at its end plays from the start
  const t = play && !prefersReducedMotion() && Number(params.t) >= 1 ? 0 : Number(params.t);
  // results hidden (ask before revealing): no samples on the hemisphere, the morph held at t = 0
  const box = useRef<HTMLDivElement>(null);
  const tl = useTimeline({
    t: ask ? 0 : t,
    play: ask ? false : play,
    setParams,
    max: 1,
    duration: animDuration(anim, n),
    visibleRef: box,
    renderHz: 0,
    shortcuts: !ask,
  });
  const [showPoints, setShowPoints] = useState(true);
  const [showGrid, setShowGrid] = useState(true);
  // revealed: the morph plays from the square (or jumps to its end for reduced motion)
  const wasAsk = useRef(ask);
  useEffect(() => {
    if (wasAsk.current && !ask) {
      if (prefersReducedMotion()) tl.seek(1);
      else tl.play();
    }
    wasAsk.current = ask;
  }, [ask, tl]);
  const image = useMemo(() => (lobe && cell ? cellImage(lobe, cell) : null), [lobe, cell]);
  const count = useCellCount(kind, seed, n, cell);
  const stratumText = describeStratum(cell, image, count, n, ask);
  const firstCell = useMemo(() => {
    const u = fillSequence2D(kind, seed, Math.max(1, n), new Float64Array(2), 0, 1, 0);
    return cellOf(u[0], u[1]);
  }, [kind, seed, n]);
  // described at the paused position (while playing, the description is announced on pause)
  const still = animFrame(lobe, kind, seed, n, anim, tl.t);
  const description = describeHemisphere({
    lobe,
    noLobe: noLobeText,
    kind,
    n,
    anim,
    t: tl.t,
    s: still.s,
    shown: still.shown,
    chi2,
    stratum: cell ? stratumText : '',
    ask,
  });
  const format = (x: number) => {
    const frame = animFrame(lobe, kind, seed, n, anim, x);
    return anim === 'warp'
      ? `t = ${x.toFixed(2)}, s = ${frame.s.toFixed(2)}`
      : `t = ${x.toFixed(2)}: ${formatCount(frame.shown)} of ${formatCount(n)}`;
  };
  const text = { tl, lobe, lobeId, kind, seed, n, anim, ask, noLobe: noLobeText };
  const animSelect = bindControls(schema, params, setParams).select('anim', 'Animation', ANIM_OPTIONS);
  const transport = (
    <TimelineTransport
      timeline={tl}
      label={anim === 'warp' ? 'Warp morph' : 'Samples appearing'}
      format={format}
      testId="timeline"
    />
  );
  const toggles = (
    <div className="hemi-toggles">
      <Toggle label="points" checked={showPoints} onChange={setShowPoints} />
      <Toggle label="warped (ξ₁, ξ₂) grid" checked={showGrid} onChange={setShowGrid} />
    </div>
  );
  // On the page, the animation's choice and the toggles are folded with the settings. On the
  // classroom stage: the view, the transport and the key readouts; the toggles go to the drawer with
  // the settings, the caption, the first sample's position and the stratum's sentence below the stage.
  return (
    <>
      <Stage
        staged={present}
        controls={
          present ? (
            <>
              {animSelect}
              {toggles}
              {settings(null)}
            </>
          ) : undefined
        }
      >
        <div className={present ? 'hemi-figure is-staged' : 'hemi-figure'} ref={box}>
          <DescribedFigure
            className="hemi-figure-main"
            label="Warp of the unit square onto the hemisphere: samples of the chosen density"
            description={description}
            playing={tl.playing}
            testId="hemi-figure"
          >
            {lobe ? (
              <LiveHemisphereView
                height={present ? stageViewHeight(ask) : 400}
                tl={tl}
                lobe={lobe}
                points={pointsArgsOf(params)}
                {...pointSet}
                anim={anim}
                showPoints={showPoints && !ask}
                showGrid={showGrid}
                cell={cell}
              />
            ) : (
              <div className="hemi-no-view">{problem}</div>
            )}
            {!lobe ? (
              // nothing to sample: the transport is there, and disabled
              <fieldset disabled className="hemi-held" data-testid="timeline-nothing">
                <legend className="small">Nothing to play: no density is sampled.</legend>
                {transport}
              </fieldset>
            ) : ask ? (
              // held at t = 0 until revealed: the transport is there, and disabled
              <fieldset disabled className="hemi-held" data-testid="timeline-held">
                <legend className="small">The warp stays at t = 0 (the square) until you reveal.</legend>
                {transport}
              </fieldset>
            ) : (
              transport
            )}
            <FigureReadouts {...text} tracked={!present} />
            {present ? null : <FigureCaption {...text} />}
          </DescribedFigure>
          <div className="hemi-figure-side">
            <SquareMemo
              {...pointSet}
              size={present ? 260 : 240}
              cell={cell}
              onPick={onPickCell}
              captioned={!present}
            />
            <StratumControls
              cell={cell}
              onPick={onPickCell}
              text={present ? '' : stratumText}
              firstCell={firstCell}
            />
            {present
              ? null
              : settings(
                  <>
                    {animSelect}
                    {toggles}
                  </>,
                )}
          </div>
        </div>
      </Stage>
      {present ? (
        <div className="hemi-after-stage">
          <FigureReadouts {...text} keys={false} />
          <FigureCaption {...text} />
          {cell ? <p className="small">{stratumText}</p> : null}
        </div>
      ) : null}
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
