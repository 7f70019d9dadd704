/**
 * Q5's figure block: the cross-section at the live position (a described figure), the case
 * banner, and the sweep's transport. On the page they stack; on the classroom stage (`present=1`)
 * the figure takes the height the first screen leaves, over the transport and beside the case and
 * the key readouts. With `ask=1` the roots, the case, the readouts and the sweep stay hidden until
 * revealed.
 */
import type { RefObject } from 'react';
import { Readout, Revealed, TimelineTransport } from '../../../ui';
import { sweepAt, type Sweep } from '../sweep';
import type { Vec3 } from '../../../core/vec3';
import type { RaySphereParams } from '../params';
import { describeRaySphere, sweepPlaceText } from '../view/describe';
import { LiveDescribed } from '../view/Described';
import { LiveCaseBanner, LiveCrossSection, useCoarseModel, type LiveProps } from '../view/Live';

export interface Q5FigureProps extends LiveProps {
  sweep: Sweep;
  /** The ends of the sweep, kept in view so the figure does not rescale while it plays. */
  ends: readonly Vec3[];
  /** An edit of the ray or sphere by dragging (coalesced to one per frame by the scene). */
  onDrag: (patch: Partial<RaySphereParams>) => void;
  method: RaySphereParams['method'];
  /** `ask=1` before Reveal: the setup only. */
  ask: boolean;
  /** Laid out for the classroom stage (the figure fills the height left). */
  staged?: boolean;
  /** The block's box on the stage (the timeline stops drawing while it is off screen). */
  boxRef?: RefObject<HTMLDivElement | null>;
}

/** The readouts a class reads off the stage: the case, Δ and the roots (at the coarse position). */
function StageReadouts(live: LiveProps) {
  const res = useCoarseModel(live).model.chosen;
  return (
    <div className="readouts rs-stage-readouts">
      <Readout id="stage-discriminant" label="Δ" value={res?.discriminant ?? null} digits={4} />
      <Readout id="stage-t0" label="t₀" value={res?.t0 ?? null} digits={4} />
      <Readout id="stage-t1" label="t₁" value={res?.t1 ?? null} digits={4} />
      {/* Unicode subscripts, not <sub>: on the stage no text may be set smaller than 18 px */}
      <Readout id="stage-t-hit" label="tₕᵢₜ" value={res?.tHit ?? null} digits={4} />
    </div>
  );
}

export function Q5Figure(props: Q5FigureProps) {
  const { tl, modelAt, sweep, ends, onDrag, method, ask, staged, boxRef } = props;
  const live = { tl, modelAt };
  // the timeline's position is τ, never t: t is the ray's parameter (on the g(t) axis beside it)
  const fmtPos = (tau: number) => sweepPlaceText({ mode: sweep.mode, tau, x: sweepAt(sweep, tau).x });
  const figure = (
    <LiveDescribed
      {...live}
      label="Cross-section through the ray and the sphere"
      describe={(m, tau) =>
        describeRaySphere(m, { method, ask, sweep: { mode: sweep.mode, tau, x: sweepAt(sweep, tau).x } })
      }
      testId="cross-figure"
    >
      <LiveCrossSection {...live} onChange={onDrag} fitExtra={ends} hideResults={ask} fill={staged} />
    </LiveDescribed>
  );
  const banner = (
    <Revealed ask={ask} what="the case (hit, miss, tangent …)">
      <LiveCaseBanner {...live} method={method} />
    </Revealed>
  );
  // the sweep's own settings (mode, extent) are under "More settings" (./Q5Controls)
  const transport = (
    <Revealed ask={ask} what="the sweep of the ray across the sphere">
      <TimelineTransport timeline={tl} label="Ray sweep" format={fmtPos} testId="timeline" />
    </Revealed>
  );
  if (!staged)
    return (
      <>
        {figure}
        {banner}
        {transport}
      </>
    );
  return (
    <div className="rs-present" ref={boxRef}>
      <div className="rs-present-fig stage-figure">{figure}</div>
      <div className="rs-present-side">
        {banner}
        <Revealed ask={ask} what="Δ and the roots">
          <StageReadouts {...live} />
        </Revealed>
      </div>
      <div className="rs-present-tl">{transport}</div>
    </div>
  );
}
