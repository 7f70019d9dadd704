/**
 * The text beside the hemisphere figure at the timeline's coarse position: the animation's readouts
 * and its caption (the caption goes below the stage in classroom mode).
 */
import { useMemo } from 'react';
import { formatNumber, Readout, useCoarsePosition, type Timeline } from '../../../ui';
import type { SequenceKind } from '../../../core/random';
import { animFrame, type AnimKind } from '../animation';
import { examInversion } from '../examChecks';
import type { Lobe } from '../lobe';
import type { LobeId } from '../params';

/** What the figure samples and animates (the figure's and its texts' common inputs). */
export interface FigureState {
  lobe: Lobe | null;
  lobeId: LobeId;
  kind: SequenceKind;
  seed: number;
  n: number;
  anim: AnimKind;
}

/** The figure's state at a coarse position (4 times a second while playing, exact when paused). */
export interface FigureTextProps extends FigureState {
  tl: Timeline;
  /** Results hidden: the caption leaves out where the samples land. */
  ask: boolean;
  /** Why nothing is sampled when there is no lobe (the caption says so instead of the animation). */
  noLobe: string;
}

function useCoarseFrame({ tl, lobe, kind, seed, n, anim }: FigureTextProps) {
  const t = useCoarsePosition(tl, 4);
  return useMemo(() => animFrame(lobe, kind, seed, n, anim, t), [lobe, kind, seed, n, anim, t]);
}

/**
 * The animation's readouts: the key ones (the morph fraction, the points on screen) and where the
 * first sample is now (`tracked`); the classroom stage shows the key ones, the rest go below it.
 */
export function FigureReadouts({
  keys = true,
  tracked = true,
  ...props
}: FigureTextProps & { keys?: boolean; tracked?: boolean }) {
  const { lobe, anim } = props;
  const frame = useCoarseFrame(props);
  const tr = frame.tracked;
  return (
    <div className="readouts hemi-anim-readouts" data-testid={keys ? 'anim-readouts' : undefined}>
      {keys ? (
        <>
          <Readout id="morph-s" label="morph s = t²(3 − 2t)" value={lobe ? frame.s : null} digits={6} />
          <Readout
            id="anim-count"
            label={anim === 'warp' ? 'points morphing' : 'points drawn at t'}
            value={lobe ? frame.shown : null}
          />
        </>
      ) : null}
      {tracked ? (
        <>
          <Readout id="tracked-x" label="first sample now at x" value={tr ? tr.pos[0] : null} digits={6} />
          <Readout id="tracked-y" label="y" value={tr ? tr.pos[1] : null} digits={6} />
          <Readout id="tracked-z" label="z" value={tr ? tr.pos[2] : null} digits={6} />
        </>
      ) : null}
    </div>
  );
}

/** The animation's caption: what moves where, and where the first sample goes. */
export function FigureCaption(props: FigureTextProps) {
  const { lobeId, anim, ask } = props;
  const tr = useCoarseFrame(props).tracked;
  const spread = lobeId === 'exam' ? examInversion(0, 1 / 8).phiLog1p : null;
  if (!props.lobe)
    return (
      <p className="small hemi-caption" data-testid="hemi-caption">
        Nothing is drawn and nothing plays: {props.noLobe}
      </p>
    );
  return (
    <p className="small hemi-caption" data-testid="hemi-caption">
      {anim === 'warp'
        ? 'At t = 0 every point (ξ₁, ξ₂) lies in the unit square drawn flat on the base plane (ξ₁ along x, ξ₂ along y); as t goes to 1 each travels to the direction the inversion of (d) gives it. Each cell of the 8 × 8 grid is a stratum of the square: follow its colour to the patch of the hemisphere it lands on.'
        : 'The samples appear in the order they are drawn, from 1 to N (geometric in t); each keeps the colour of its (ξ₁, ξ₂).'}
      {spread !== null && !ask
        ? ` For the exam's lobe, ξ₁ sets θ = arcsin √ξ₁ (rings) and ξ₂ sets φ: the first stratum ξ₂ < 1/8 spreads over φ ∈ [0, ${formatNumber(spread, 3)}) rad, where p ∝ eᵠ is small, while the last one is squeezed near φ = 2π.`
        : ''}
      {tr && !ask
        ? ` The first sample (ξ₁, ξ₂) = (${formatNumber(tr.xi1, 4)}, ${formatNumber(tr.xi2, 4)}) goes to θ = ${formatNumber(tr.theta, 4)}, φ = ${formatNumber(tr.phi, 4)} (ringed in the square).`
        : ''}
    </p>
  );
}
