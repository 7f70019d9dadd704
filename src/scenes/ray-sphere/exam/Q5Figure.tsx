/**
 * Q5's figure block: the cross-section at the live position, the case banner, and the sweep's
 * transport with the sweep's own controls (mode and extent).
 */
import { NumberField, Select, TimelineTransport } from '../../../ui';
import { sweepAt, type Sweep, type V3 } from '../model';
import type { RaySphereParams } from '../params';
import { describeRaySphere, sweepPlaceText } from '../view/describe';
import { LiveDescribed } from '../view/Described';
import { LiveCaseBanner, LiveCrossSection, type LiveProps } from '../view/Live';

export interface Q5FigureProps extends LiveProps {
  sweep: Sweep;
  extent: number;
  /** The ends of the sweep, kept in view so the figure does not rescale while it plays. */
  ends: readonly V3[];
  /** An edit of the ray or sphere by dragging (coalesced to one per frame by the scene). */
  onDrag: (patch: Partial<RaySphereParams>) => void;
  setParams: (patch: Partial<RaySphereParams>) => void;
  method: RaySphereParams['method'];
}

export function Q5Figure({ tl, modelAt, sweep, extent, ends, onDrag, setParams, method }: Q5FigureProps) {
  // the timeline's position is τ, never t: t is the ray's parameter (on the g(t) axis beside it)
  const fmtPos = (tau: number) => sweepPlaceText({ mode: sweep.mode, tau, x: sweepAt(sweep, tau).x });
  return (
    <>
      <LiveDescribed
        tl={tl}
        modelAt={modelAt}
        label="Cross-section through the ray and the sphere"
        describe={(m, tau) =>
          describeRaySphere(m, { method, sweep: { mode: sweep.mode, tau, x: sweepAt(sweep, tau).x } })
        }
        testId="cross-figure"
      >
        <LiveCrossSection tl={tl} modelAt={modelAt} onChange={onDrag} fitExtra={ends} />
        <LiveCaseBanner tl={tl} modelAt={modelAt} />
      </LiveDescribed>
      <TimelineTransport timeline={tl} label="Ray sweep" format={fmtPos} testId="timeline">
        <div className="rs-sweep-controls">
          <Select
            label="Sweep"
            value={sweep.mode}
            options={[
              { value: 'offset', label: 'origin moves across the ray' },
              { value: 'rotate', label: 'direction turns about o' },
            ]}
            onChange={(m) => setParams({ sweep: m })}
            testId="sweep-mode"
          />
          <NumberField
            label={sweep.mode === 'offset' ? 'extent (± radii)' : 'extent (± angular radii)'}
            value={extent}
            onChange={(x) => setParams({ extent: x })}
            min={0.05}
            max={1000}
            step={0.5}
            testId="sweep-extent"
          />
        </div>
      </TimelineTransport>
    </>
  );
}
