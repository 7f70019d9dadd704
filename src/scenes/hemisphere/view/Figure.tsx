/**
 * The figure of Q1 on the shared timeline: the warp morph of the unit square onto the hemisphere
 * (or the samples appearing one by one), its transport and toggles, the readouts and caption at the
 * current position, and the unit square beside it with the scene's settings.
 */
import { memo, useMemo, useRef, useState, type ComponentProps, type ReactNode } from 'react';
import type { SceneProps } from '../../../kit/scene';
import {
  formatNumber,
  Readout,
  Select,
  TimelineTransport,
  Toggle,
  useCoarsePosition,
  useTimeline,
  useTimelineFrame,
  type Timeline,
} from '../../../ui';
import { formatCount } from '../../../ui/format';
import type { SequenceKind } from '../../../core/random';
import { animDuration, animFrame, examInversion, type AnimFrame, type AnimKind, type Lobe } from '../model';
import type { HemisphereSchema, LobeId } from '../params';
import type { PointsArgs } from '../jobs';
// Static, not lazy: the 3D panel is on the first screen, and a Suspense fallback of another height
// shifted the layout when it arrived (three.js itself still loads lazily, inside Viewport).
import { HemisphereView } from './HemisphereView';
import { UnitSquare } from './UnitSquare';

const ANIM_OPTIONS: { value: AnimKind; label: string }[] = [
  { value: 'warp', label: 'warp morph: square → hemisphere' },
  { value: 'grow', label: 'samples appear, 1 → N' },
];

const SquareMemo = memo(UnitSquare);

interface FigureProps {
  lobe: Lobe | null;
  /** What the 3D view's points depend on (../jobs pointsArgsOf). */
  points: PointsArgs;
  lobeId: LobeId;
  kind: SequenceKind;
  seed: number;
  n: number;
  anim: AnimKind;
  t: number;
  play: boolean;
  setParams: SceneProps<HemisphereSchema>['setParams'];
  present: boolean;
  problem: ReactNode;
  settings: ReactNode;
}

/**
 * The figure on the shared timeline. While playing nothing here re-renders per frame: the 3D view
 * is driven directly from the timeline's frames (LiveHemisphereView), the readouts and caption
 * follow a coarse position (FigureText, 4 times a second), the transport writes its own position;
 * the unit square and the settings are memoised. Paused, everything renders the exact position.
 */
export function Figure({
  lobe,
  points,
  lobeId,
  kind,
  seed,
  n,
  anim,
  t,
  play,
  setParams,
  present,
  problem,
  settings,
}: FigureProps) {
  const box = useRef<HTMLDivElement>(null);
  const tl = useTimeline({
    t,
    play,
    setParams,
    max: 1,
    duration: animDuration(anim, n),
    visibleRef: box,
    renderHz: 0,
  });
  const [showPoints, setShowPoints] = useState(true);
  const [showGrid, setShowGrid] = useState(true);
  const format = (x: number) => {
    const frame = animFrame(lobe, kind, seed, n, anim, x);
    return anim === 'warp'
      ? `t = ${x.toFixed(2)}, s = ${frame.s.toFixed(2)}`
      : `t = ${x.toFixed(2)}: ${formatCount(frame.shown)} of ${formatCount(n)}`;
  };
  return (
    <div className="hemi-figure" ref={box}>
      <div className="hemi-figure-main">
        {lobe ? (
          <LiveHemisphereView
            tl={tl}
            lobe={lobe}
            points={points}
            kind={kind}
            seed={seed}
            n={n}
            anim={anim}
            showPoints={showPoints}
            showGrid={showGrid}
            height={present ? 520 : 400}
          />
        ) : (
          <div className="hemi-no-view">{problem}</div>
        )}
        <TimelineTransport
          timeline={tl}
          label={anim === 'warp' ? 'Warp morph' : 'Samples appearing'}
          format={format}
          testId="timeline"
        >
          <Select
            label="Animation"
            value={anim}
            options={ANIM_OPTIONS}
            onChange={(v) => setParams({ anim: v })}
            testId="anim"
          />
        </TimelineTransport>
        <div className="hemi-toggles">
          <Toggle label="points" checked={showPoints} onChange={setShowPoints} />
          <Toggle label="warped (ξ₁, ξ₂) grid" checked={showGrid} onChange={setShowGrid} />
        </div>
        <FigureText tl={tl} lobe={lobe} lobeId={lobeId} kind={kind} seed={seed} n={n} anim={anim} />
      </div>
      <div className="hemi-figure-side">
        <SquareMemo kind={kind} seed={seed} n={n} size={present ? 260 : 220} />
        {settings}
      </div>
    </div>
  );
}

/** The animation's readouts and caption at a coarse position (4 times a second while playing, exact when paused). */
function FigureText({
  tl,
  lobe,
  lobeId,
  kind,
  seed,
  n,
  anim,
}: {
  tl: Timeline;
  lobe: FigureProps['lobe'];
  lobeId: FigureProps['lobeId'];
  kind: SequenceKind;
  seed: number;
  n: number;
  anim: AnimKind;
}) {
  const t = useCoarsePosition(tl, 4);
  const frame = useMemo(() => animFrame(lobe, kind, seed, n, anim, t), [lobe, kind, seed, n, anim, t]);
  const tr = frame.tracked;
  const spread = lobeId === 'exam' ? examInversion(0, 1 / 8).phiLog1p : null;
  return (
    <>
      <div className="readouts hemi-anim-readouts" data-testid="anim-readouts">
        <Readout id="morph-s" label="morph s = t²(3 − 2t)" value={lobe ? frame.s : null} digits={6} />
        <Readout
          id="anim-count"
          label={anim === 'warp' ? 'points morphing' : 'points drawn at t'}
          value={lobe ? frame.shown : null}
        />
        <Readout id="tracked-x" label="first sample now at x" value={tr ? tr.pos[0] : null} digits={6} />
        <Readout id="tracked-y" label="y" value={tr ? tr.pos[1] : null} digits={6} />
        <Readout id="tracked-z" label="z" value={tr ? tr.pos[2] : null} digits={6} />
      </div>
      <p className="small hemi-caption">
        {anim === 'warp'
          ? 'At t = 0 every point (ξ₁, ξ₂) lies in the unit square drawn flat on the base plane (ξ₁ along x, ξ₂ along y); as t goes to 1 each travels to the direction the inversion of (d) gives it. Each cell of the 8 × 8 grid is a stratum of the square: follow its colour to the patch of the hemisphere it lands on.'
          : 'The samples appear in the order they are drawn, from 1 to N (geometric in t); each keeps the colour of its (ξ₁, ξ₂).'}
        {spread !== null
          ? ` For the exam's lobe, ξ₁ sets θ = arcsin √ξ₁ (rings) and ξ₂ sets φ: the first stratum ξ₂ < 1/8 spreads over φ ∈ [0, ${formatNumber(spread, 3)}) rad, where p ∝ e^φ is small, while the last one is squeezed near φ = 2π.`
          : ''}
        {tr
          ? ` The first sample (ξ₁, ξ₂) = (${formatNumber(tr.xi1, 4)}, ${formatNumber(tr.xi2, 4)}) goes to θ = ${formatNumber(tr.theta, 4)}, φ = ${formatNumber(tr.phi, 4)} (ringed in the square).`
          : ''}
      </p>
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
